// Skinning and morph data: JOINTS_n/WEIGHTS_n and morph targets per primitive, skins,
// default morph weights. Invalid data is an ImportError naming the object; data that
// can be repaired (unnormalised or zero weights, weight lists of the wrong length) is
// repaired with a counted warning. Nothing here is allocated for static primitives.
#include "accessor_reader.h"
#include "import_context.h"
#include "import_error.h"
#include "motion_internal.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

std::vector<glm::vec3> read_vec3s(ImportContext& ctx, int accessor, std::uint32_t count,
                                  const std::string& path) {
    std::uint32_t nc = 0;
    const auto values = read_accessor_floats(ctx.model, accessor, {3}, nc, path);
    if (values.size() / 3 != count)
        fail(path + ": has " + std::to_string(values.size() / 3) + " elements but POSITION has " +
             std::to_string(count));
    std::vector<glm::vec3> out(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        out[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
        if (!core::is_finite(out[i]))
            fail(path + "[" + std::to_string(i) + "] is not finite (NaN or Inf)");
    }
    return out;
}

// JOINTS_n: unsigned byte or short, not normalised. WEIGHTS_n: float, or normalised
// unsigned byte/short. Both VEC4, one element per vertex.
void read_influence_set(ImportContext& ctx, const tinygltf::Primitive& prim, int set,
                        std::uint32_t count, const std::string& where, PrimitiveMotion& m) {
    const std::string jn = "JOINTS_" + std::to_string(set), wn = "WEIGHTS_" + std::to_string(set);
    const auto jit = prim.attributes.find(jn), wit = prim.attributes.find(wn);
    const std::string jpath = where + ".attributes." + jn, wpath = where + ".attributes." + wn;
    if (wit == prim.attributes.end()) fail(jpath + ": has no matching " + wn);
    const AccessorSource js = describe_accessor(ctx.model, jit->second);
    const AccessorSource ws = describe_accessor(ctx.model, wit->second);
    if ((js.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         js.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
        js.normalized)
        fail(jpath + ": must be unsigned byte or unsigned short, not normalized (componentType " +
             std::to_string(js.component_type) + ")");
    if (!(ws.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          (ws.normalized && (ws.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             ws.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))))
        fail(wpath + ": must be float or normalized unsigned byte/short (componentType " +
             std::to_string(ws.component_type) + ")");
    std::uint32_t nc = 0;
    const auto joints = read_accessor_floats(ctx.model, jit->second, {4}, nc, jpath);
    const auto weights = read_accessor_floats(ctx.model, wit->second, {4}, nc, wpath);
    if (joints.size() / 4 != count || weights.size() / 4 != count)
        fail(where + ": " + jn + "/" + wn + " do not have POSITION's " + std::to_string(count) +
             " elements");
    const std::uint32_t first = m.influences;
    const std::uint32_t stride = first + 4;
    // Re-layout the earlier sets' data for the wider stride.
    std::vector<std::uint16_t> j(std::size_t{count} * stride);
    std::vector<float> w(std::size_t{count} * stride);
    for (std::uint32_t v = 0; v < count; ++v) {
        for (std::uint32_t k = 0; k < first; ++k) {
            j[v * stride + k] = m.joints[v * first + k];
            w[v * stride + k] = m.weights[v * first + k];
        }
        for (std::uint32_t k = 0; k < 4; ++k) {
            const float wk = weights[4 * v + k];
            if (!std::isfinite(wk) || wk < 0.0f)
                fail(wpath + "[" + std::to_string(v) + "] has weight " + number_text(wk) +
                     " (weights must be finite and non-negative)");
            j[v * stride + first + k] = static_cast<std::uint16_t>(joints[4 * v + k]);
            w[v * stride + first + k] = wk;
        }
    }
    m.joints = std::move(j);
    m.weights = std::move(w);
    m.influences = stride;
}

// glTF requires the weights of a vertex to sum to 1. Float weights are divided by their
// sum (as three.js does for float data); quantised ones only when clearly off, since
// 8-bit rounding alone leaves them a few 1/255 from 1. A vertex whose weights are all 0
// cannot be skinned: it follows its first joint (three.js does the same).
void normalise_weights(ImportContext& ctx, const std::string& where, PrimitiveMotion& m,
                       bool quantised) {
    const std::uint32_t n = m.influences;
    const std::size_t count = m.weights.size() / n;
    std::uint32_t off = 0, zero = 0;
    for (std::size_t v = 0; v < count; ++v) {
        float* w = &m.weights[v * n];
        double sum = 0.0;
        for (std::uint32_t k = 0; k < n; ++k) sum += w[k];
        if (sum <= 0.0) {
            ++zero;
            w[0] = 1.0f;
            continue;
        }
        const bool far = std::abs(sum - 1.0) > (quantised ? 2e-2 : 1e-3);
        if (far) ++off;
        if (far || !quantised)
            for (std::uint32_t k = 0; k < n; ++k) w[k] = static_cast<float>(w[k] / sum);
    }
    if (off)
        ctx.warn(where + ": " + std::to_string(off) +
                 " vertices' skin weights do not sum to 1; divided by their sum");
    if (zero)
        ctx.warn(where + ": " + std::to_string(zero) +
                 " vertices have all skin weights 0; each follows its first joint");
    for (std::size_t i = 0; i < m.weights.size(); ++i)
        if (m.weights[i] > 0.0f) m.max_joint = std::max<std::uint32_t>(m.max_joint, m.joints[i]);
}

} // namespace

std::int32_t import_primitive_motion(ImportContext& ctx, const tinygltf::Primitive& prim,
                                     const std::string& where, const std::vector<float>& positions,
                                     PrimitiveInfo& info) {
    const auto count = static_cast<std::uint32_t>(positions.size() / 3);
    info.morph_targets = static_cast<std::uint32_t>(prim.targets.size());
    int sets = 0;
    while (prim.attributes.count("JOINTS_" + std::to_string(sets))) ++sets;
    if (sets == 0 && prim.attributes.count("WEIGHTS_0"))
        fail(where + ".attributes.WEIGHTS_0: has no matching JOINTS_0");
    if (sets == 0 && prim.targets.empty()) return -1;

    PrimitiveMotion m;
    m.mesh = info.mesh;
    m.primitive = info.primitive;
    m.base_positions.resize(count);
    for (std::uint32_t i = 0; i < count; ++i)
        m.base_positions[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    bool quantised = false;
    for (int s = 0; s < sets; ++s) {
        read_influence_set(ctx, prim, s, count, where, m);
        const auto ws =
            describe_accessor(ctx.model, prim.attributes.at("WEIGHTS_" + std::to_string(s)));
        quantised = quantised || ws.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT;
    }
    if (sets) normalise_weights(ctx, where, m, quantised);
    for (std::size_t t = 0; t < prim.targets.size(); ++t) {
        MorphTarget target;
        const std::string tpath = where + ".targets[" + std::to_string(t) + "]";
        for (const auto& [name, accessor] : prim.targets[t]) {
            auto* stream = name == "POSITION"  ? &target.position
                           : name == "NORMAL"  ? &target.normal
                           : name == "TANGENT" ? &target.tangent
                                               : nullptr;
            if (!stream) {
                ctx.warn(tpath + "." + name +
                         ": morph target attribute ignored (Sherpa morphs "
                         "POSITION, NORMAL and TANGENT)");
                continue;
            }
            *stream = read_vec3s(ctx, accessor, count, tpath + "." + name);
            if (std::find(m.target_attributes.begin(), m.target_attributes.end(), name) ==
                m.target_attributes.end())
                m.target_attributes.push_back(name);
        }
        m.targets.push_back(std::move(target));
    }
    compute_influence_boxes(m);
    ctx.scene.motions.push_back(std::move(m));
    return static_cast<std::int32_t>(ctx.scene.motions.size() - 1);
}

void import_skins(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    const std::size_t nodes = scene.nodes.size();
    for (std::size_t s = 0; s < model.skins.size(); ++s) {
        const auto& src = model.skins[s];
        const std::string where = "skins[" + std::to_string(s) + "]";
        Skin skin;
        skin.name = src.name;
        if (src.joints.empty()) fail(where + ".joints: is empty");
        for (int j : src.joints) {
            if (j < 0 || static_cast<std::size_t>(j) >= nodes)
                fail(where + ".joints: node " + std::to_string(j) + " out of range (file has " +
                     std::to_string(nodes) + " nodes)");
            skin.joints.push_back(static_cast<std::uint32_t>(j));
        }
        if (src.skeleton < -1 || src.skeleton >= static_cast<int>(nodes))
            fail(where + ".skeleton: node " + std::to_string(src.skeleton) + " out of range");
        skin.skeleton = src.skeleton;
        skin.inverse_bind.assign(skin.joints.size(), glm::mat4(1.0f));
        if (src.inverseBindMatrices >= 0) try {
                const std::string path = where + ".inverseBindMatrices";
                std::uint32_t nc = 0, degenerate = 0;
                const auto v = read_accessor_floats(model, src.inverseBindMatrices, {16}, nc, path);
                if (v.size() / 16 < skin.joints.size())
                    fail(path + ": has " + std::to_string(v.size() / 16) + " matrices for " +
                         std::to_string(skin.joints.size()) + " joints");
                for (std::size_t j = 0; j < skin.joints.size(); ++j) {
                    for (int k = 0; k < 16; ++k)
                        glm::value_ptr(skin.inverse_bind[j])[k] = v[16 * j + k];
                    if (!core::is_finite(skin.inverse_bind[j]))
                        fail(path + "[" + std::to_string(j) + "] is not finite");
                    if (std::abs(glm::determinant(skin.inverse_bind[j])) < 1e-12f) ++degenerate;
                }
                // A singular inverse bind matrix collapses its vertices (no NaN follows: the
                // matrix is only multiplied, never inverted); the file is shown as it is.
                if (degenerate)
                    ctx.warn(path + ": " + std::to_string(degenerate) +
                             " singular matrices (their joints' vertices collapse)");
            } catch (const ImportError& e) { // drawn with identity matrices, and named
                skin.inverse_bind.assign(skin.joints.size(), glm::mat4(1.0f));
                ctx.skip("SHERPA_SKIN_MATRICES_SKIPPED",
                         std::string(e.what()) + " (identity inverse bind matrices used)");
            }
        scene.skins.push_back(std::move(skin));
    }
    // A skinned node's primitives must index only that skin's joints.
    for (std::size_t n = 0; n < nodes; ++n) {
        const Node& node = scene.nodes[n];
        if (node.skin < 0 || node.mesh < 0) continue;
        const Skin& skin = scene.skins[static_cast<std::size_t>(node.skin)];
        for (const auto& p : scene.primitives) {
            if (p.mesh != static_cast<std::uint32_t>(node.mesh) || p.motion < 0) continue;
            const PrimitiveMotion& m = scene.motions[static_cast<std::size_t>(p.motion)];
            if (m.skinned() && m.max_joint >= skin.joints.size())
                fail("nodes[" + std::to_string(n) + "]: meshes[" + std::to_string(p.mesh) +
                     "].primitives[" + std::to_string(p.primitive) + "] uses joint " +
                     std::to_string(m.max_joint) + " but skins[" + std::to_string(node.skin) +
                     "] has " + std::to_string(skin.joints.size()) + " joints");
        }
    }
}

// Default morph weights: the node's, else its mesh's, else zeros; a list of the wrong
// length is padded with zeros or cut, with a warning.
void import_default_weights(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    std::vector<std::uint32_t> targets(model.meshes.size(), 0);
    for (const auto& p : scene.primitives) {
        auto& t = targets[p.mesh];
        if (t != 0 && p.morph_targets != 0 && p.morph_targets != t)
            fail("meshes[" + std::to_string(p.mesh) +
                 "]: primitives have different numbers of "
                 "morph targets (" +
                 std::to_string(t) + " and " + std::to_string(p.morph_targets) + ")");
        t = std::max(t, p.morph_targets);
    }
    auto fit = [&](const std::vector<double>& given, std::uint32_t n, const std::string& where) {
        std::vector<float> w(n, 0.0f);
        for (std::size_t i = 0; i < given.size() && i < n; ++i) {
            if (!std::isfinite(given[i])) fail(where + "[" + std::to_string(i) + "] is not finite");
            w[i] = static_cast<float>(given[i]);
        }
        if (!given.empty() && given.size() != n)
            ctx.warn(where + ": " + std::to_string(given.size()) + " weights for " +
                     std::to_string(n) + " morph targets; " +
                     (given.size() < n ? "missing ones are 0" : "extra ones ignored"));
        return w;
    };
    scene.mesh_weights.resize(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        scene.mesh_weights[m] =
            fit(model.meshes[m].weights, targets[m], "meshes[" + std::to_string(m) + "].weights");
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        const auto mesh = static_cast<std::size_t>(node.mesh);
        node.weights = model.nodes[n].weights.empty()
                           ? scene.mesh_weights[mesh]
                           : fit(model.nodes[n].weights, targets[mesh],
                                 "nodes[" + std::to_string(n) + "].weights");
    }
}

} // namespace sherpa::scene::detail
