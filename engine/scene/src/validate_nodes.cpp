// The node graph, scenes and skins: parents, loops, transforms, what skinned nodes
// need (validate_internal.h).
#include "validate_internal.h"

#include <algorithm>
#include <cmath>

namespace sherpa::scene::detail {
namespace {

bool has_joints(const Json& mesh) {
    const Json& prims = Validation::member(mesh, "primitives");
    if (!prims.is_array()) return false;
    for (const Json& p : prims) {
        const Json& attrs = Validation::member(p, "attributes");
        // Khronos counts a primitive as skinned only with both sets.
        if (attrs.is_object() && attrs.contains("JOINTS_0") && attrs.contains("WEIGHTS_0"))
            return true;
    }
    return false;
}

std::size_t target_count(const Json& mesh) {
    const Json& prims = Validation::member(mesh, "primitives");
    if (!prims.is_array() || prims.empty()) return 0;
    const Json& t = Validation::member(prims[0], "targets");
    return t.is_array() ? t.size() : 0;
}

// A matrix glTF can decompose into TRS: last row (0, 0, 0, 1), invertible 3x3.
bool decomposable(const Json& m) {
    double a[16];
    for (int i = 0; i < 16; ++i) a[i] = m[static_cast<std::size_t>(i)].get<double>();
    if (a[3] != 0 || a[7] != 0 || a[11] != 0 || a[15] != 1) return false;
    const double det = a[0] * (a[5] * a[10] - a[9] * a[6]) - a[4] * (a[1] * a[10] - a[9] * a[2]) +
                       a[8] * (a[1] * a[6] - a[5] * a[2]);
    return std::isfinite(det) && std::abs(det) > 1e-30;
}

} // namespace

void validate_nodes(Validation& v) {
    const Json& nodes = v.array("nodes");
    const std::size_t n = nodes.size();
    std::vector<std::int64_t> parent(n, -1);
    std::vector<std::uint8_t> is_joint(n, 0);
    std::vector<std::uint8_t> skinned_node(n, 0); // a mesh and a skin, both resolved
    // Per mesh, whether it is skinned (computed once: many nodes share a mesh).
    const Json& meshes = v.array("meshes");
    std::vector<std::uint8_t> skinned_mesh(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) skinned_mesh[m] = has_joints(meshes[m]);
    for (const Json& skin : v.array("skins")) {
        for (const Json& j : Validation::member(skin, "joints"))
            if (is_int(j) && as_int(j) >= 0 && static_cast<std::size_t>(as_int(j)) < n)
                is_joint[static_cast<std::size_t>(as_int(j))] = 1;
        if (const std::int64_t s = ref(v, skin, "skeleton", "nodes"); s >= 0)
            is_joint[static_cast<std::size_t>(s)] = 1;
    }
    static const Json null;
    for (std::size_t i = 0; i < n; ++i) {
        const Json& node = nodes[i];
        if (!node.is_object()) continue;
        // Built only for a message: most nodes have none.
        auto where = [i] { return ptr("/nodes", i); };
        // The members this pass reads, in one walk over the node's keys (a look-up per
        // member cost more than the checks on a file of many small nodes).
        const Json *children_p = &null, *matrix_p = &null, *rotation_p = &null, *weights_p = &null,
                   *mesh_p = &null, *skin_p = &null;
        bool has_trs = false, has_skin = false, has_camera = false, has_extensions = false;
        for (auto it = node.begin(); it != node.end(); ++it) {
            const std::string& key = it.key();
            if (key == "children")
                children_p = &*it;
            else if (key == "matrix")
                matrix_p = &*it;
            else if (key == "rotation")
                rotation_p = &*it, has_trs = true;
            else if (key == "weights")
                weights_p = &*it;
            else if (key == "translation" || key == "scale")
                has_trs = true;
            else if (key == "mesh")
                mesh_p = &*it;
            else if (key == "skin")
                skin_p = &*it, has_skin = true;
            else if (key == "camera")
                has_camera = true;
            else if (key == "extensions")
                has_extensions = true;
        }
        const Json& children = *children_p;
        if (children.is_array())
            for (std::size_t k = 0; k < children.size(); ++k) {
                if (!is_int(children[k])) continue;
                const std::int64_t c = as_int(children[k]);
                if (c < 0 || static_cast<std::size_t>(c) >= n) continue;
                std::int64_t& p = parent[static_cast<std::size_t>(c)];
                if (p >= 0 && p != static_cast<std::int64_t>(i))
                    v.add("NODE_PARENT_OVERRIDE", Severity::Error, ptr(ptr(where(), "children"), k),
                          "Value overrides parent of node " + std::to_string(c) + ".");
                else
                    p = static_cast<std::int64_t>(i);
            }
        const Json& matrix = *matrix_p;
        bool matrix_ok = matrix.is_array() && matrix.size() == 16;
        for (const Json& x : matrix) matrix_ok &= x.is_number();
        if (matrix_ok) {
            if (has_trs)
                v.add("NODE_MATRIX_TRS", Severity::Error, ptr(where(), "matrix"),
                      "A node can have either a matrix or any combination of "
                      "translation/rotation/scale "
                      "(TRS) properties.");
            bool identity = true;
            for (int k = 0; k < 16; ++k)
                identity &=
                    matrix[static_cast<std::size_t>(k)].get<double>() == (k % 5 == 0 ? 1.0 : 0.0);
            if (identity)
                v.add("NODE_MATRIX_DEFAULT", Severity::Information, ptr(where(), "matrix"),
                      "Do not specify default transform matrix.");
            else if (!decomposable(matrix))
                v.add("NODE_MATRIX_NON_TRS", Severity::Error, ptr(where(), "matrix"),
                      "Matrix must be decomposable to TRS.");
        }
        const Json& rotation = *rotation_p;
        if (rotation.is_array() && rotation.size() == 4) {
            double len2 = 0;
            bool in_range = true;
            for (const Json& x : rotation) {
                if (!x.is_number())
                    in_range = false;
                else {
                    const double c = x.get<double>();
                    in_range &= c >= -1 && c <= 1;
                    len2 += c * c;
                }
            }
            if (in_range && std::abs(std::sqrt(len2) - 1.0) > 0.000005)
                v.add("ROTATION_NON_UNIT", Severity::Error, ptr(where(), "rotation"),
                      "Rotation quaternion must be normalized.");
        }
        auto index_into = [](const Json& j, std::size_t size) -> std::int64_t {
            const std::int64_t k = is_int(j) ? as_int(j) : -1;
            return k >= 0 && static_cast<std::uint64_t>(k) < size ? k : -1;
        };
        const std::int64_t mesh = index_into(*mesh_p, meshes.size());
        const std::int64_t skin = index_into(*skin_p, v.size("skins"));
        skinned_node[i] = mesh >= 0 && skin >= 0;
        if (mesh >= 0) {
            const Json& m = meshes[static_cast<std::size_t>(mesh)];
            const bool skinned = skinned_mesh[static_cast<std::size_t>(mesh)] != 0;
            if (has_skin && !skinned)
                v.add("NODE_SKIN_WITH_NON_SKINNED_MESH", Severity::Error, where(),
                      "Node has skin defined, but mesh has no joints data.");
            if (!has_skin && skinned)
                v.add("NODE_SKINNED_MESH_WITHOUT_SKIN", Severity::Warning, where(),
                      "Node uses skinned mesh, but has no skin defined.");
            if (skin >= 0 && skinned && (has_trs || matrix_ok))
                v.add("NODE_SKINNED_MESH_LOCAL_TRANSFORMS", Severity::Warning, where(),
                      "Local transforms will not affect a skinned mesh.");
            const Json& weights = *weights_p;
            if (weights.is_array() && weights.size() != target_count(m))
                v.add("NODE_WEIGHTS_INVALID", Severity::Error, ptr(where(), "weights"),
                      "The length of weights array (" + std::to_string(weights.size()) +
                          ") does not match the number of morph targets (" +
                          std::to_string(target_count(m)) + ").");
            // Joint indices of the mesh's skinned primitives are checked against this skin.
            if (skin >= 0) {
                const std::uint64_t joints =
                    Validation::member(v.array("skins")[static_cast<std::size_t>(skin)], "joints")
                        .size();
                const std::string prefix =
                    ptr(ptr("/meshes", static_cast<std::size_t>(mesh)), "primitives");
                for (auto& u : v.usages)
                    if (u.use == AccessorUse::Joints && u.pointer.starts_with(prefix) &&
                        u.limit == 0)
                        u.limit = joints;
            }
        }
        const bool empty = !has_camera && children_p == &null && mesh < 0 && !has_skin &&
                           !has_extensions && !is_joint[i];
        if (empty && v.accepting())
            v.add("NODE_EMPTY", Severity::Information, where(), "Empty node encountered.");
    }
    // Loops: walk up from every node; a walk longer than n has met a cycle.
    std::vector<std::uint8_t> in_loop(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        std::int64_t at = parent[i];
        std::size_t steps = 0;
        while (at >= 0 && at != static_cast<std::int64_t>(i) && steps++ <= n)
            at = parent[static_cast<std::size_t>(at)];
        if (at == static_cast<std::int64_t>(i)) in_loop[i] = 1;
    }
    for (std::size_t i = 0; i < n; ++i)
        if (in_loop[i])
            v.add("NODE_LOOP", Severity::Error, ptr("/nodes", i), "Node is a part of a node loop.");
    auto root_of = [&](std::int64_t i) {
        std::size_t steps = 0;
        while (parent[static_cast<std::size_t>(i)] >= 0 && steps++ <= n)
            i = parent[static_cast<std::size_t>(i)];
        return i;
    };
    for (std::size_t i = 0; i < n; ++i)
        if (parent[i] >= 0 && !in_loop[i] && skinned_node[i])
            v.add("NODE_SKINNED_MESH_NON_ROOT", Severity::Warning, ptr("/nodes", i),
                  "Node with a skinned mesh is not root. Parent transforms will not affect a "
                  "skinned mesh.");

    const Json& scenes = v.array("scenes");
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const Json& roots = Validation::member(scenes[s], "nodes");
        for (std::size_t k = 0; k < roots.size() && roots.is_array(); ++k)
            if (is_int(roots[k]) && as_int(roots[k]) >= 0 &&
                static_cast<std::size_t>(as_int(roots[k])) < n &&
                parent[static_cast<std::size_t>(as_int(roots[k]))] >= 0)
                v.add("SCENE_NON_ROOT_NODE", Severity::Error,
                      ptr(ptr(ptr("/scenes", s), "nodes"), k),
                      "Node " + std::to_string(as_int(roots[k])) + " is not a root node.");
    }

    const Json& skins = v.array("skins");
    const Json& accessors = v.array("accessors");
    for (std::size_t s = 0; s < skins.size(); ++s) {
        const Json& skin = skins[s];
        if (!skin.is_object()) continue;
        const std::string where = ptr("/skins", s);
        const Json& joints = Validation::member(skin, "joints");
        std::int64_t common = -2;
        bool common_ok = joints.is_array() && !joints.empty();
        for (const Json& j : joints) {
            if (!is_int(j) || as_int(j) < 0 || static_cast<std::size_t>(as_int(j)) >= n) {
                common_ok = false;
                continue;
            }
            if (in_loop[static_cast<std::size_t>(as_int(j))]) continue;
            const std::int64_t r = root_of(as_int(j));
            if (common == -2)
                common = r;
            else if (common != r)
                common_ok = false;
        }
        if (joints.is_array() && !joints.empty() && !common_ok)
            v.add("SKIN_NO_COMMON_ROOT", Severity::Error, ptr(where, "joints"),
                  "Joints do not have a common root.");
        if (const std::int64_t sk = ref(v, skin, "skeleton", "nodes"); sk >= 0 && common_ok) {
            bool ancestor = true;
            for (const Json& j : joints) {
                std::int64_t at = as_int(j);
                std::size_t steps = 0;
                while (at >= 0 && at != sk && steps++ <= n)
                    at = parent[static_cast<std::size_t>(at)];
                ancestor &= at == sk;
            }
            if (!ancestor)
                v.add("SKIN_SKELETON_INVALID", Severity::Error, ptr(where, "skeleton"),
                      "Skeleton node is not a common root.");
        }
        if (const std::int64_t ibm = ref(v, skin, "inverseBindMatrices", "accessors"); ibm >= 0) {
            const Json& acc = accessors[static_cast<std::size_t>(ibm)];
            const std::string ip = ptr(where, "inverseBindMatrices");
            v.use_accessor(ibm, AccessorRole::IBM, ViewRole::IBM, ip);
            if (!(acc.contains("type") && acc["type"] == "MAT4") ||
                int_or(acc, "componentType", 0) != 5126)
                v.add("SKIN_IBM_INVALID_FORMAT", Severity::Error, ip,
                      "Invalid IBM accessor format. Must be one of ('{MAT4, FLOAT}').");
            else if (joints.is_array() &&
                     int_or(acc, "count", 0) < static_cast<std::int64_t>(joints.size()))
                v.add("INVALID_IBM_ACCESSOR_COUNT", Severity::Error, ip,
                      "IBM accessor must have at least " + std::to_string(joints.size()) +
                          " elements. Found " + std::to_string(int_or(acc, "count", 0)) + ".");
            else
                v.usages.push_back(
                    {static_cast<std::size_t>(ibm), AccessorUse::InverseBindMatrices, ip});
        }
    }
}

} // namespace sherpa::scene::detail
