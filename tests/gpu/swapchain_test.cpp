// Swapchain path: an X11 window made with xcb in this test only (window-system
// types stay out of the engine), a VkSurfaceKHR from it, frames presented under
// the validation layer, a resize, the environment's background, and the pixels read
// back from the X server.
// Run under Xvfb (CTest: tests/xvfb_exec.sh); without a display the tests are skipped.
#define VK_USE_PLATFORM_XCB_KHR
#include <vulkan/vulkan.h>
#include <xcb/xcb.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/presenter.h>
#include <sherpa/render/comparison.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/presented_frame.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/scene_loader.h>

namespace {

using namespace sherpa;

// A mapped xcb window; closed on destruction.
struct XcbWindow {
    xcb_connection_t* connection = nullptr;
    xcb_window_t window = 0;
    std::uint32_t width, height;

    XcbWindow(std::uint32_t w, std::uint32_t h) : width(w), height(h) {
        connection = xcb_connect(nullptr, nullptr);
        if (xcb_connection_has_error(connection)) return;
        xcb_screen_t* screen = xcb_setup_roots_iterator(xcb_get_setup(connection)).data;
        window = xcb_generate_id(connection);
        const std::uint32_t values[] = {screen->black_pixel};
        xcb_create_window(connection, XCB_COPY_FROM_PARENT, window, screen->root, 0, 0,
                          std::uint16_t(w), std::uint16_t(h), 0, XCB_WINDOW_CLASS_INPUT_OUTPUT,
                          screen->root_visual, XCB_CW_BACK_PIXEL, values);
        xcb_map_window(connection, window);
        xcb_flush(connection);
    }
    ~XcbWindow() {
        if (window) xcb_destroy_window(connection, window);
        if (connection) xcb_disconnect(connection);
    }
    bool ok() const { return connection && !xcb_connection_has_error(connection) && window; }
    void resize(std::uint32_t w, std::uint32_t h) {
        const std::uint32_t values[] = {w, h};
        xcb_configure_window(connection, window, XCB_CONFIG_WINDOW_WIDTH | XCB_CONFIG_WINDOW_HEIGHT,
                             values);
        xcb_flush(connection);
        width = w;
        height = h;
    }
    // Distinct 32-bit pixel values in the window's current contents.
    std::size_t distinct_pixels() {
        auto* reply =
            xcb_get_image_reply(connection,
                                xcb_get_image(connection, XCB_IMAGE_FORMAT_Z_PIXMAP, window, 0, 0,
                                              std::uint16_t(width), std::uint16_t(height), ~0u),
                                nullptr);
        if (!reply) return 0;
        const std::uint8_t* data = xcb_get_image_data(reply);
        const int len = xcb_get_image_data_length(reply);
        std::vector<std::uint32_t> seen;
        for (int i = 0; i + 3 < len && seen.size() < 64; i += 4 * 7) {
            std::uint32_t p;
            std::memcpy(&p, data + i, 4);
            p &= 0x00ffffffu;
            if (std::find(seen.begin(), seen.end(), p) == seen.end()) seen.push_back(p);
        }
        std::free(reply);
        return seen.size();
    }
};

VkSurfaceKHR make_surface(const gpu::Context& context, const XcbWindow& window) {
    auto sci =
        gpu::vk_init<VkXcbSurfaceCreateInfoKHR>(VK_STRUCTURE_TYPE_XCB_SURFACE_CREATE_INFO_KHR);
    sci.connection = window.connection;
    sci.window = window.window;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateXcbSurfaceKHR(context.instance(), &sci, nullptr, &surface),
                  "vkCreateXcbSurfaceKHR");
    return surface;
}

// A validated context that presents to xcb windows.
gpu::ContextOptions presenting_options() {
    gpu::ContextOptions options;
    options.validation = true;
    options.presentation = true;
    options.instance_extensions = {VK_KHR_XCB_SURFACE_EXTENSION_NAME};
    return options;
}

class SwapchainTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display (run under Xvfb)";
    }
};

TEST_F(SwapchainTest, PresentsFramesAndSurvivesResizeWithoutValidationMessages) {
    XcbWindow window(160, 120);
    ASSERT_TRUE(window.ok());
    gpu::Context context(presenting_options());

    VkSurfaceKHR surface = make_surface(context, window);
    {
        render::Renderer renderer(context);
        scene::LoadResult scene = scene::load_scene("builtin:default");
        ASSERT_TRUE(scene) << scene.error;
        renderer.load(*scene.scene);
        gpu::Presenter presenter(context, renderer.resources(), surface, window.width,
                                 window.height);
        EXPECT_EQ(presenter.extent().width, 160u);
        EXPECT_GE(presenter.image_count(), 2u);
        render::FrameRequest settings;
        settings.overlays = render::kOverlayBounds;
        int shown = 0;
        render::PresentedFrame frame(renderer, settings);
        for (int i = 0; i < 6; ++i) shown += presenter.present_frame(frame) ? 1 : 0;
        EXPECT_GE(shown, 5);
        context.wait_idle(); // both frames in flight have completed
        vkQueueWaitIdle(context.queue());
        // The scene, not only the black window background, reached the X server.
        EXPECT_GT(window.distinct_pixels(), 4u);

        window.resize(200, 100);
        presenter.resize(200, 100);
        EXPECT_EQ(presenter.extent().width, 200u);
        EXPECT_EQ(presenter.extent().height, 100u);
        for (int i = 0; i < 4; ++i) presenter.present_frame(frame);
        EXPECT_GE(presenter.frames_presented(), 8u);

        // The environment behind the scene: drawn into the swapchain image for a first
        // view, then kept while the view holds still and copied into the swapchain
        // images (lavapipe's take transfer writes); drawn into the reduced-resolution
        // image at half scale.
        const render::EnvironmentImage room = render::room_environment(256);
        renderer.set_environment(&room);
        presenter.present_frame(frame);
        const std::uint64_t drawn = renderer.resident().render_target_bytes;
        for (int i = 0; i < 4; ++i) presenter.present_frame(frame);
        EXPECT_GE(renderer.resident().render_target_bytes, drawn + 200u * 100u * 4u);
        render::PresentedFrame half(renderer, settings, 0.5f);
        for (int i = 0; i < 3; ++i) presenter.present_frame(half);
        context.wait_idle();
        renderer.set_environment(nullptr);
    }
    vkDestroySurfaceKHR(context.instance(), surface, nullptr);
    for (const auto& m : context.validation().messages())
        ADD_FAILURE() << m.id_name << ": " << m.text;
}

// The viewport's raster / RT / split / difference switch through a real swapchain:
// a ray-traced frame (full and half resolution), then comparison frames of two
// renderers on the context (raster against rays), the second renderer's timeline
// signalled by the presenter's submission.
TEST_F(SwapchainTest, PresentsRayTracedAndComparisonFrames) {
    XcbWindow window(96, 72);
    ASSERT_TRUE(window.ok());
    gpu::Context context(presenting_options());
    if (!context.info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    VkSurfaceKHR surface = make_surface(context, window);
    {
        scene::LoadResult scene = scene::load_scene("builtin:default");
        ASSERT_TRUE(scene) << scene.error;
        render::Renderer raster(context);
        render::RendererOptions rt_options;
        rt_options.ray_tracing = true;
        render::Renderer rays(context, rt_options);
        raster.load(*scene.scene);
        rays.load(*scene.scene);
        gpu::Presenter presenter(context, rays.resources(), surface, window.width, window.height);
        render::FrameRequest settings;
        settings.view = render::DebugView::Normal;
        render::FrameRequest rt = settings;
        rt.renderer = render::RendererKind::RayTraced;
        for (float scale : {1.0f, 0.5f}) {
            render::PresentedFrame frame(rays, rt, scale);
            for (int i = 0; i < 3; ++i) presenter.present_frame(frame);
        }
        context.wait_idle();
        EXPECT_GT(window.distinct_pixels(), 2u);
        for (render::CompareMode mode :
             {render::CompareMode::Split, render::CompareMode::Difference}) {
            render::ComparisonSettings compare;
            compare.mode = mode;
            for (int i = 0; i < 4; ++i) {
                // Made per frame, as the editor does; a is the presenter's renderer.
                render::ComparisonFrame frame(rays, rt, raster, settings, compare);
                presenter.present_frame(frame);
                if (i == 3) {
                    EXPECT_TRUE(frame.completed_comparison().valid);
                    EXPECT_EQ(frame.completed_comparison().pixels, 96u * 72u);
                    // Normals agree inside the model, not along its silhouettes.
                    EXPECT_LT(frame.completed_comparison().mean, 0.05);
                }
            }
        }
        context.wait_idle();
        EXPECT_GE(presenter.frames_presented(), 14u);
    }
    vkDestroySurfaceKHR(context.instance(), surface, nullptr);
    for (const auto& m : context.validation().messages())
        ADD_FAILURE() << m.id_name << ": " << m.text;
}

TEST_F(SwapchainTest, ContextWithoutPresentationRefusesASurface) {
    XcbWindow window(64, 64);
    ASSERT_TRUE(window.ok());
    gpu::ContextOptions options;
    options.validation = true;
    options.instance_extensions = {VK_KHR_SURFACE_EXTENSION_NAME,
                                   VK_KHR_XCB_SURFACE_EXTENSION_NAME};
    gpu::Context context(options);
    VkSurfaceKHR surface = make_surface(context, window);
    {
        render::Renderer renderer(context);
        EXPECT_THROW(gpu::Presenter(context, renderer.resources(), surface, 64, 64), gpu::GpuError);
    }
    vkDestroySurfaceKHR(context.instance(), surface, nullptr);
    EXPECT_EQ(context.validation().count(), 0u);
}

} // namespace
