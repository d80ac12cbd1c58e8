#include <sherpa/render/emissive_lights.h>

#include <cmath>

namespace sherpa::gpu {

float emitted_luminance(const MaterialInstance& m) {
    if (m.unlit) return 0.0f;
    const glm::vec3 e = m.emissive_factor * m.emissive_strength;
    const float lum = 0.2126f * e.r + 0.7152f * e.g + 0.0722f * e.b;
    return std::isfinite(lum) && lum > 0.0f ? lum : 0.0f;
}

EmissiveLights emissive_lights(const Scene& scene, std::size_t max_triangles) {
    EmissiveLights out;
    std::vector<float> luminance(scene.materials.size(), 0.0f);
    bool any = false;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const MaterialInstance& m = scene.materials[i];
        const float lum = emitted_luminance(m);
        if (lum > kMaxEmissiveLuminance) {
            out.warnings.push_back("material " + std::to_string(i) + " '" + m.name +
                                   "': emitted luminance " + std::to_string(lum) +
                                   " is beyond 1e20; not sampled as a light (its samples are "
                                   "capped at 1e20)");
            continue;
        }
        luminance[i] = lum;
        any = any || lum > 0.0f;
    }
    if (!any) return out;
    if (!scene.animations.empty() || !scene.motions.empty()) {
        out.warnings.push_back("the scene animates: its emissive triangles are found by "
                               "BSDF sampling only (no light list)");
        return out;
    }
    // A material variant switched after loading may change what emits: a list of the
    // loaded variant would bias the others, so BSDF sampling alone finds them.
    for (const VariantMeshMapping& v : scene.variants.meshes)
        for (std::int32_t m : v.materials)
            if (m >= 0 && std::size_t(m) < luminance.size() &&
                v.default_material < luminance.size() &&
                luminance[std::size_t(m)] != luminance[v.default_material]) {
                out.warnings.push_back("a material variant changes which surfaces emit: its "
                                       "emissive triangles are found by BSDF sampling only (no "
                                       "light list)");
                return out;
            }
    std::vector<double> power;
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size() || inst.material_id >= luminance.size()) continue;
        const float lum = luminance[inst.material_id];
        const Mesh& mesh = scene.meshes[inst.mesh_id];
        if (!(lum > 0.0f) || mesh.topology() != Topology::Triangles) continue;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            glm::vec3 p[3];
            bool valid = true;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[t + std::size_t(k)];
                if (v >= mesh.vertices.size()) {
                    valid = false;
                    break;
                }
                p[k] = glm::vec3(inst.world * glm::vec4(mesh.vertices[v].position, 1.0f));
            }
            if (!valid || !is_finite(p[0]) || !is_finite(p[1]) || !is_finite(p[2])) continue;
            const glm::vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
            const double area = 0.5 * double(glm::length(glm::cross(e1, e2)));
            if (!(area > 0.0) || !std::isfinite(area)) continue; // degenerate: never hit
            if (out.triangles.size() == max_triangles) {
                out.warnings.push_back("more than " + std::to_string(max_triangles) +
                                       " emissive triangles: none sampled as lights");
                return EmissiveLights{{}, 0.0f, 0.0, std::move(out.warnings)};
            }
            out.triangles.push_back(
                {glm::vec4(p[0], 0.0f), glm::vec4(e1, lum), glm::vec4(e2, 0.0f)});
            power.push_back(double(lum) * area);
        }
    }
    double total = 0.0;
    for (double w : power) total += w;
    if (out.triangles.empty() || !(total > 0.0) || !std::isfinite(total) ||
        !std::isfinite(float(1.0 / total)) || float(1.0 / total) == 0.0f) {
        if (!out.triangles.empty())
            out.warnings.push_back("the emissive triangles' total power is not representable; "
                                   "none sampled as lights");
        return EmissiveLights{{}, 0.0f, 0.0, std::move(out.warnings)};
    }
    double running = 0.0;
    for (std::size_t i = 0; i < out.triangles.size(); ++i) {
        running += power[i];
        EmissiveTriangle& tri = out.triangles[i];
        tri.p0_cdf.w = i + 1 == out.triangles.size() ? 1.0f : float(running / total);
        tri.e1_density.w = float(double(tri.e1_density.w) / total);
    }
    out.power = total;
    out.inv_power = float(1.0 / total);
    return out;
}

} // namespace sherpa::gpu
