#include "vertex_motion_columns.h"

#include <QStringList>

#include <array>
#include <cstring>
#include <limits>
#include <map>

#include "format_values.h"

namespace sherpa::editor {

namespace {
constexpr std::uint32_t kNone = ~0u;

std::array<std::uint32_t, 3> bits(const glm::vec3& p) {
    std::array<std::uint32_t, 3> b{};
    std::memcpy(b.data(), &p.x, sizeof(b));
    return b;
}
} // namespace

void VertexMotionColumns::set(const scene::Scene* scene, int mesh) {
    motion_ = nullptr;
    columns_.clear();
    source_.clear();
    if (!scene || mesh < 0 || static_cast<std::size_t>(mesh) >= scene->meshes.size()) return;
    for (const scene::PrimitiveInfo& p : scene->primitives)
        if (p.engine_mesh == mesh && p.motion >= 0 &&
            static_cast<std::size_t>(p.motion) < scene->motions.size())
            motion_ = &scene->motions[static_cast<std::size_t>(p.motion)];
    if (!motion_) return;
    const scene::Mesh& m = scene->meshes[static_cast<std::size_t>(mesh)];
    const std::vector<glm::vec3>& base = motion_->base_positions;

    // Engine vertex -> file vertex. Unsplit vertices keep their file index; copies
    // (and every vertex of an unwelded mesh) are found by their position's bits.
    source_.assign(m.vertices.size(), kNone);
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> by_position;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const glm::vec3& p = m.vertices[v].position;
        if (!m.unwelded && v < base.size() && bits(base[v]) == bits(p)) {
            source_[v] = static_cast<std::uint32_t>(v);
            continue;
        }
        if (by_position.empty())
            for (std::size_t f = base.size(); f-- > 0;)
                by_position[bits(base[f])] = static_cast<std::uint32_t>(f); // first wins
        if (const auto it = by_position.find(bits(p)); it != by_position.end())
            source_[v] = it->second;
    }

    if (motion_->skinned()) {
        columns_.push_back({What::Joints});
        columns_.push_back({What::Weights});
    }
    for (std::uint32_t t = 0; t < motion_->targets.size(); ++t) {
        const scene::MorphTarget& target = motion_->targets[t];
        if (!target.position.empty()) columns_.push_back({What::DeltaPosition, t});
        if (!target.normal.empty()) columns_.push_back({What::DeltaNormal, t});
        if (!target.tangent.empty()) columns_.push_back({What::DeltaTangent, t});
    }
}

std::int64_t VertexMotionColumns::sourceVertex(std::size_t vertex) const {
    return vertex < source_.size() && source_[vertex] != kNone
               ? static_cast<std::int64_t>(source_[vertex])
               : -1;
}

QString VertexMotionColumns::header(int column) const {
    if (column < 0 || column >= count()) return {};
    const Column& c = columns_[static_cast<std::size_t>(column)];
    switch (c.what) {
    case What::Joints:
        return QStringLiteral("JOINTS");
    case What::Weights:
        return QStringLiteral("WEIGHTS");
    case What::DeltaPosition:
        return QStringLiteral("Δpos %1").arg(c.target);
    case What::DeltaNormal:
        return QStringLiteral("Δnrm %1").arg(c.target);
    case What::DeltaTangent:
        return QStringLiteral("Δtan %1").arg(c.target);
    }
    return {};
}

const std::vector<glm::vec3>* VertexMotionColumns::delta(const Column& c) const {
    const scene::MorphTarget& t = motion_->targets[c.target];
    return c.what == What::DeltaPosition ? &t.position
           : c.what == What::DeltaNormal ? &t.normal
                                         : &t.tangent;
}

QString VertexMotionColumns::text(std::size_t vertex, int column) const {
    const std::int64_t f = sourceVertex(vertex);
    if (f < 0 || column < 0 || column >= count()) return QStringLiteral("—");
    const auto src = static_cast<std::size_t>(f);
    const Column& c = columns_[static_cast<std::size_t>(column)];
    if (c.what == What::Joints || c.what == What::Weights) {
        const std::size_t n = motion_->influences;
        if ((src + 1) * n > motion_->joints.size()) return QStringLiteral("—");
        QStringList parts;
        for (std::size_t k = 0; k < n; ++k)
            parts << (c.what == What::Joints
                          ? QString::number(motion_->joints[src * n + k])
                          : format::number(static_cast<double>(motion_->weights[src * n + k])));
        return parts.join(QLatin1Char(' '));
    }
    const std::vector<glm::vec3>& d = *delta(c);
    return src < d.size() ? format::vec(d[src]) : QStringLiteral("—");
}

double VertexMotionColumns::key(std::size_t vertex, int column) const {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const std::int64_t f = sourceVertex(vertex);
    if (f < 0 || column < 0 || column >= count()) return nan;
    const auto src = static_cast<std::size_t>(f);
    const Column& c = columns_[static_cast<std::size_t>(column)];
    if (c.what == What::Joints || c.what == What::Weights) {
        const std::size_t i = src * motion_->influences;
        if (i >= motion_->joints.size()) return nan;
        return c.what == What::Joints ? motion_->joints[i] : motion_->weights[i];
    }
    const std::vector<glm::vec3>& d = *delta(c);
    return src < d.size() ? static_cast<double>(glm::length(d[src])) : nan;
}

} // namespace sherpa::editor
