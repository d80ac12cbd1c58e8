#include <sherpa/scene/mesh_pass.h>

#include <algorithm>

#include <glm/glm.hpp>

namespace sherpa::scene {

std::uint32_t pipeline_key(AlphaMode mode, bool double_sided, bool mirrored) {
    return static_cast<std::uint32_t>(mode) << 2 | (double_sided ? 2u : 0u) | (mirrored ? 1u : 0u);
}

PipelineState pipeline_state(std::uint32_t key) {
    return {static_cast<AlphaMode>(key >> 2), (key & 2u) != 0, (key & 1u) != 0};
}

std::uint32_t instance_pipeline_key(const Scene& scene, std::uint32_t instance) {
    const MeshInstance& inst = scene.instances[instance];
    const MaterialInstance& m = scene.materials[inst.material_id];
    return pipeline_key(m.alpha_mode, m.double_sided,
                        glm::determinant(glm::mat3(inst.world)) < 0.0f);
}

std::uint32_t MeshPass::add(std::uint32_t instance, std::uint32_t mesh_id, std::uint32_t pipeline) {
    std::uint32_t handle;
    if (!free_handles_.empty()) {
        handle = free_handles_.back();
        free_handles_.pop_back();
    } else {
        handle = static_cast<std::uint32_t>(objects_.size());
        objects_.emplace_back();
        is_dirty_.push_back(0);
    }
    const std::uint64_t key = (std::uint64_t{pipeline} << 32) | mesh_id;
    objects_[handle] = PassObject{instance, key, true};
    pending_add_.push_back({key, handle});
    ++live_;
    mark_dirty(handle); // new objects need their data uploaded too
    return handle;
}

bool MeshPass::remove(std::uint32_t handle) {
    if (handle >= objects_.size() || !objects_[handle].alive) return false;
    objects_[handle].alive = false;
    pending_remove_.push_back(handle);
    --live_;
    return true;
}

void MeshPass::mark_dirty(std::uint32_t handle) {
    if (handle >= objects_.size() || is_dirty_[handle]) return;
    is_dirty_[handle] = 1;
    dirty_.push_back(handle);
}

void MeshPass::update() {
    if (!pending_remove_.empty()) {
        // Handles are recycled only here, after their flat entries are gone, so a
        // flat entry of a removed handle is always stale.
        std::vector<std::uint8_t> removed(objects_.size(), 0);
        for (std::uint32_t h : pending_remove_) removed[h] = 1;
        std::erase_if(flat_, [&](const FlatBatch& b) { return removed[b.object] != 0; });
        std::erase_if(pending_add_, [&](const FlatBatch& b) { return removed[b.object] != 0; });
        free_handles_.insert(free_handles_.end(), pending_remove_.begin(), pending_remove_.end());
        pending_remove_.clear();
    }
    if (!pending_add_.empty()) {
        auto by_key = [](const FlatBatch& a, const FlatBatch& b) {
            return a.sort_key != b.sort_key ? a.sort_key < b.sort_key : a.object < b.object;
        };
        std::sort(pending_add_.begin(), pending_add_.end(), by_key);
        std::vector<FlatBatch> merged(flat_.size() + pending_add_.size());
        std::merge(flat_.begin(), flat_.end(), pending_add_.begin(), pending_add_.end(),
                   merged.begin(), by_key);
        flat_ = std::move(merged);
        pending_add_.clear();
    }
    batches_.clear();
    multi_.clear();
    for (std::uint32_t i = 0; i < flat_.size(); ++i) {
        const std::uint64_t key = flat_[i].sort_key;
        if (batches_.empty() ||
            (std::uint64_t{batches_.back().pipeline} << 32 | batches_.back().mesh_id) != key)
            batches_.push_back(
                {static_cast<std::uint32_t>(key), static_cast<std::uint32_t>(key >> 32), i, 0});
        ++batches_.back().count;
    }
    for (std::uint32_t b = 0; b < batches_.size(); ++b) {
        if (multi_.empty() || batches_[multi_.back().first].pipeline != batches_[b].pipeline)
            multi_.push_back({b, 0});
        ++multi_.back().count;
    }
}

ScenePasses build_mesh_passes(const Scene& scene) {
    ScenePasses passes;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const MeshInstance& inst = scene.instances[i];
        const std::uint32_t key = instance_pipeline_key(scene, i);
        if (pipeline_state(key).alpha_mode == AlphaMode::Blend) {
            passes.transparent.add(i, inst.mesh_id, key);
        } else {
            passes.forward.add(i, inst.mesh_id, key);
            passes.shadow.add(i, inst.mesh_id, key);
        }
    }
    for (MeshPass* p : {&passes.forward, &passes.transparent, &passes.shadow}) {
        p->update();
        p->clear_dirty(); // the first upload sends everything anyway
    }
    return passes;
}

} // namespace sherpa::scene
