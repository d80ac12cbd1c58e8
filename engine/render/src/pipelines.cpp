#include "pipelines.h"
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/gpu_structs.h>

#include "depth_mask_frag.h"
#include "depth_vert.h"
#include "flat_frag.h"
#include "floor_frag.h"
#include "forward_frag.h"
#include "glyph_vert.h"
#include "lines_vert.h"
#include "mesh_vert.h"

#include <span>
#include <vector>

namespace sherpa::render {

namespace {

gpu::UniqueShaderModule make_module(VkDevice device, std::span<const std::uint32_t> code) {
    return gpu::create_shader_module(device, code, "vkCreateShaderModule");
}

} // namespace

gpu::UniquePipeline make_graphics_pipeline(VkDevice device, VkPipelineLayout layout,
                                           VkFormat color_format, const PipelineDesc& d,
                                           const char* what) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    auto stage = gpu::vk_init<VkPipelineShaderStageCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    stage.pName = "main";
    stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
    stage.module = d.vert;
    stage.pSpecializationInfo = d.vert_constants;
    stages.push_back(stage);
    if (d.frag) {
        stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stage.module = d.frag;
        stage.pSpecializationInfo = d.frag_constants;
        stages.push_back(stage);
    }
    // Vertex pulling: no vertex input bindings at all.
    auto vertex_input = gpu::vk_init<VkPipelineVertexInputStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    auto assembly = gpu::vk_init<VkPipelineInputAssemblyStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    assembly.topology = d.topology;
    auto viewport = gpu::vk_init<VkPipelineViewportStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    auto raster = gpu::vk_init<VkPipelineRasterizationStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    raster.polygonMode = d.polygon;
    raster.lineWidth = d.line_width;
    auto multisample = gpu::vk_init<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    auto depth = gpu::vk_init<VkPipelineDepthStencilStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
    depth.depthTestEnable = VK_TRUE; // compare op and writes are dynamic
    VkPipelineColorBlendAttachmentState attachment{};
    attachment.colorWriteMask = d.write_color
                                    ? VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                          VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT
                                    : 0;
    if (d.blend) {
        // glTF BLEND: straight alpha over what is behind.
        attachment.blendEnable = VK_TRUE;
        attachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        attachment.colorBlendOp = VK_BLEND_OP_ADD;
        attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        attachment.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    auto blend = gpu::vk_init<VkPipelineColorBlendStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    blend.attachmentCount = d.color ? 1 : 0;
    blend.pAttachments = &attachment;
    // Viewport and scissor first: a pipeline without depth has only those two.
    const VkDynamicState dynamic_states[] = {
        VK_DYNAMIC_STATE_VIEWPORT,          VK_DYNAMIC_STATE_SCISSOR,
        VK_DYNAMIC_STATE_CULL_MODE,         VK_DYNAMIC_STATE_FRONT_FACE,
        VK_DYNAMIC_STATE_DEPTH_COMPARE_OP,  VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE,
        VK_DYNAMIC_STATE_DEPTH_BIAS_ENABLE, VK_DYNAMIC_STATE_DEPTH_BIAS,
    };
    auto dynamic = gpu::vk_init<VkPipelineDynamicStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    dynamic.dynamicStateCount =
        d.depth ? static_cast<std::uint32_t>(std::size(dynamic_states)) : 2u;
    dynamic.pDynamicStates = dynamic_states;
    auto rendering = gpu::vk_init<VkPipelineRenderingCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
    rendering.colorAttachmentCount = d.color ? 1 : 0;
    rendering.pColorAttachmentFormats = &color_format;
    rendering.depthAttachmentFormat = d.depth ? kDepthFormat : VK_FORMAT_UNDEFINED;

    auto ci =
        gpu::vk_init<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    ci.pNext = &rendering;
    ci.stageCount = static_cast<std::uint32_t>(stages.size());
    ci.pStages = stages.data();
    ci.pVertexInputState = &vertex_input;
    ci.pInputAssemblyState = &assembly;
    ci.pViewportState = &viewport;
    ci.pRasterizationState = &raster;
    ci.pMultisampleState = &multisample;
    ci.pDepthStencilState = d.depth ? &depth : nullptr;
    ci.pColorBlendState = &blend;
    ci.pDynamicState = &dynamic;
    ci.layout = layout;
    VkPipeline p = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &p), what);
    return gpu::UniquePipeline(device, p);
}

Pipelines::Pipelines(const gpu::Context& context, VkDescriptorSetLayout textures_layout,
                     VkDescriptorSetLayout frame_layout, VkFormat color_format,
                     bool transmission_background)
    : color_format_(color_format),
      transmission_background_(transmission_background ? VK_TRUE : VK_FALSE),
      point_size_(context.info().large_points ? kPointSizePixels : 1.0f),
      line_width_(context.info().wide_lines ? kLineWidthPixels : 1.0f),
      outline_width_(context.info().wide_lines ? kOutlineWidthPixels : 1.0f),
      device_(context.device()) {
    VkDevice device = context.device();
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                             sizeof(GPUPushConstants)};
    const VkDescriptorSetLayout set_layouts[] = {textures_layout, frame_layout};
    layout_ =
        gpu::create_pipeline_layout(device, set_layouts, {&push, 1}, "vkCreatePipelineLayout");
    const VkPipelineLayout layout = layout_.get();

    // Kept: forward() variants and MOTION twins are built on first use.
    mesh_vert_ = make_module(device, spirv_mesh_vert);
    forward_frag_ = make_module(device, spirv_forward_frag);
    depth_vert_ = make_module(device, spirv_depth_vert);
    glyph_vert_ = make_module(device, spirv_glyph_vert);
    lines_vert_ = make_module(device, spirv_lines_vert);
    depth_mask_frag_ = make_module(device, spirv_depth_mask_frag);
    flat_frag_ = make_module(device, spirv_flat_frag);
    floor_frag_ = make_module(device, spirv_floor_frag);
    const VkShaderModule depth_vert = depth_vert_.get(), glyph_vert = glyph_vert_.get(),
                         lines_vert = lines_vert_.get(), depth_mask_frag = depth_mask_frag_.get(),
                         flat_frag = flat_frag_.get(), floor_frag = floor_frag_.get();

    auto make = [&](PipelineId id, const PipelineDesc& d) {
        descs_[static_cast<std::size_t>(id)] = d;
        pipelines_[static_cast<std::size_t>(id)] =
            make_graphics_pipeline(device, layout, color_format, d);
    };
    make(PipelineId::PrepassOpaque,
         {depth_vert, VK_NULL_HANDLE, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_POLYGON_MODE_FILL,
          true, false, false});
    make(PipelineId::PrepassMask, {depth_vert, depth_mask_frag, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
                                   VK_POLYGON_MODE_FILL, true, false, false});
    make(PipelineId::Wireframe,
         {depth_vert, floor_frag, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, VK_POLYGON_MODE_LINE});
    make(PipelineId::Glyphs, {glyph_vert, flat_frag, VK_PRIMITIVE_TOPOLOGY_LINE_LIST});
    make(PipelineId::BoxLines, {lines_vert, flat_frag, VK_PRIMITIVE_TOPOLOGY_LINE_LIST});
    make(PipelineId::Floor, {depth_vert, floor_frag});
    PipelineDesc tint{depth_vert, floor_frag};
    tint.blend = true;
    make(PipelineId::Tint, tint);
    PipelineDesc outline{depth_vert, floor_frag, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
                         VK_POLYGON_MODE_LINE};
    outline.line_width = outline_width_;
    make(PipelineId::Outline, outline);
    make(PipelineId::ShadowOpaque, {depth_vert, VK_NULL_HANDLE, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
                                    VK_POLYGON_MODE_FILL, false, false, false});
    make(PipelineId::ShadowMask, {depth_vert, depth_mask_frag, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
                                  VK_POLYGON_MODE_FILL, false, false, false});
}

VkPipeline Pipelines::get(PipelineId id, std::uint32_t mesh_flags) {
    const auto i = static_cast<std::size_t>(id);
    if (!is_moving_mesh(mesh_flags)) return pipelines_[i].get();
    if (!motion_[i]) {
        // MOTION (constant_id 1 of the vertex stages, motion.glsl) on.
        const VkSpecializationMapEntry entry{1, 0, sizeof(VkBool32)};
        const VkBool32 on = VK_TRUE;
        const VkSpecializationInfo constants{1, &entry, sizeof(on), &on};
        PipelineDesc d = descs_[i];
        d.vert_constants = &constants;
        motion_[i] = make_graphics_pipeline(device_, layout_.get(), color_format_, d);
    }
    return motion_[i].get();
}

VkPipeline Pipelines::forward(std::uint32_t view, bool blend, std::uint32_t streams) {
    auto& p = forward_[{view, blend, streams}];
    if (!p) {
        const VkSpecializationMapEntry entries[] = {
            {0, 0, sizeof(std::uint32_t)},
            {1, sizeof(std::uint32_t), sizeof(std::uint32_t)},
            {2, 2 * sizeof(std::uint32_t), sizeof(VkBool32)}};
        const std::uint32_t values[] = {view, streams & ~kMeshMotionBit, transmission_background_};
        VkSpecializationInfo constants{3, entries, sizeof(values), values};
        // POINT_SIZE (constant_id 0) and MOTION (constant_id 1) of mesh.vert.
        struct {
            float point_size;
            VkBool32 motion;
        } vert_values{point_size_, is_moving_mesh(streams) ? VK_TRUE : VK_FALSE};
        const VkSpecializationMapEntry vert_entries[] = {{0, 0, sizeof(float)},
                                                         {1, sizeof(float), sizeof(VkBool32)}};
        VkSpecializationInfo vert_constants{2, vert_entries, sizeof(vert_values), &vert_values};
        PipelineDesc d{mesh_vert_.get(), forward_frag_.get()};
        d.blend = blend;
        d.frag_constants = &constants;
        d.vert_constants = &vert_constants;
        d.topology = (streams & kMeshPointsBit)  ? VK_PRIMITIVE_TOPOLOGY_POINT_LIST
                     : (streams & kMeshLinesBit) ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                                 : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        if (streams & kMeshLinesBit) d.line_width = line_width_;
        p = make_graphics_pipeline(device_, layout_.get(), color_format_, d);
    }
    return p.get();
}

} // namespace sherpa::render
