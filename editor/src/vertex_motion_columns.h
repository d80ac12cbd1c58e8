#pragma once
// The vertex table's motion columns (issue 16), for a primitive that skins or morphs:
// JOINTS and WEIGHTS (all of a vertex's influences in one cell each) and, per morph
// target, its POSITION / NORMAL / TANGENT deltas. The motion data is in the file's
// vertex order while the table lists the engine mesh's vertices, which may have been
// split (flat-normal unwelding, tangent seams): each engine vertex is mapped to the
// file vertex it was copied from (identity where the mesh was not split, else the
// first file vertex at the same position); a vertex with no match shows "—".
#include <QString>

#include <cstdint>
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

class VertexMotionColumns {
public:
    // `mesh`: index into scene->meshes; no columns for static meshes or a null scene.
    void set(const scene::Scene* scene, int mesh);
    int count() const { return static_cast<int>(columns_.size()); }
    QString header(int column) const;
    QString text(std::size_t vertex, int column) const;
    // Sort key: the first value of the cell (NaN: none).
    double key(std::size_t vertex, int column) const;
    // The file vertex an engine vertex shows (-1: none); for tests.
    std::int64_t sourceVertex(std::size_t vertex) const;

private:
    enum class What : std::uint8_t { Joints, Weights, DeltaPosition, DeltaNormal, DeltaTangent };
    struct Column {
        What what;
        std::uint32_t target = 0;
    };
    const std::vector<glm::vec3>* delta(const Column& c) const;

    const scene::PrimitiveMotion* motion_ = nullptr;
    std::vector<Column> columns_;
    std::vector<std::uint32_t> source_; // engine vertex -> file vertex (kNone: no match)
};

} // namespace sherpa::editor
