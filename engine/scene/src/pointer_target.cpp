// JSON pointer -> Scene object (pointer_target.h).
#include <sherpa/scene/pointer_target.h>

#include <algorithm>
#include <charconv>
#include <optional>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {
namespace {

// RFC 6901 reference tokens; nullopt for a pointer that is not "" or "/...", or a
// "~" not followed by 0 or 1.
std::optional<std::vector<std::string>> split_pointer(std::string_view p) {
    std::vector<std::string> tokens;
    if (p.empty()) return tokens;
    if (p.front() != '/') return std::nullopt;
    std::string token;
    for (std::size_t i = 1; i <= p.size(); ++i) {
        if (i == p.size() || p[i] == '/') {
            tokens.push_back(std::move(token));
            token.clear();
        } else if (p[i] == '~') {
            if (i + 1 >= p.size() || (p[i + 1] != '0' && p[i + 1] != '1')) return std::nullopt;
            token += p[++i] == '0' ? '~' : '/';
        } else {
            token += p[i];
        }
    }
    return tokens;
}

// A JSON array index: digits only, no leading zero (RFC 6901), fits int32.
std::optional<std::int32_t> array_index(const std::string& t) {
    if (t.empty() || (t.size() > 1 && t[0] == '0')) return std::nullopt;
    std::int32_t v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || v < 0) return std::nullopt;
    return v;
}

bool in(std::int32_t i, std::size_t size) {
    return i >= 0 && static_cast<std::size_t>(i) < size;
}

// A node that places engine mesh `mesh` in the displayed scene, or -1.
std::int32_t node_of_mesh(const Scene& s, std::int32_t mesh) {
    for (const MeshInstance& inst : s.instances)
        if (static_cast<std::int32_t>(inst.mesh_id) == mesh)
            return static_cast<std::int32_t>(inst.node_id);
    return -1;
}

// The first node whose `field` is `value` (displayed-scene nodes first).
template <typename Field> std::int32_t node_with(const Scene& s, Field field, std::int32_t value) {
    for (const std::uint32_t n : s.displayed_nodes)
        if (s.nodes[n].*field == value) return static_cast<std::int32_t>(n);
    for (std::size_t n = 0; n < s.nodes.size(); ++n)
        if (s.nodes[n].*field == value) return static_cast<std::int32_t>(n);
    return -1;
}

// Calls f(accessor, engine mesh, attribute) for every accessor an engine mesh read.
template <typename F> void for_each_accessor_use(const Scene& s, F&& f) {
    for (std::size_t m = 0; m < s.meshes.size(); ++m) {
        const Mesh& mesh = s.meshes[m];
        for (std::size_t a = 0; a < kVertexAttributeCount; ++a)
            if (mesh.sources[a] && mesh.sources[a]->accessor >= 0)
                f(mesh.sources[a]->accessor, static_cast<std::int32_t>(m),
                  std::string(gltf_name(static_cast<VertexAttribute>(a))));
        if (mesh.index_source && mesh.index_source->accessor >= 0)
            f(mesh.index_source->accessor, static_cast<std::int32_t>(m), std::string("indices"));
    }
}

std::string join_rest(const std::vector<std::string>& tokens, std::size_t from) {
    std::string out;
    for (std::size_t i = from; i < tokens.size(); ++i) out += '/' + json_pointer_token(tokens[i]);
    return out;
}

void resolve_primitive(const Scene& s, PointerTarget& t) {
    t.kind = TargetKind::Primitive;
    const auto& prims = s.mesh_primitives[static_cast<std::size_t>(t.index)];
    t.engine_mesh = prims[static_cast<std::size_t>(t.sub)];
    if (t.engine_mesh >= 0) {
        t.material = static_cast<std::int32_t>(
            s.meshes[static_cast<std::size_t>(t.engine_mesh)].material_id);
        t.node = node_of_mesh(s, t.engine_mesh);
    }
    if (t.node < 0) t.node = node_with(s, &Node::mesh, t.index);
}

// Top-level arrays: resolves tokens[0..] into `t`; returns the tokens used.
std::size_t resolve_tokens(const Scene& s, const std::vector<std::string>& tok, PointerTarget& t) {
    if (tok.empty()) return 0;
    const std::string& top = tok[0];
    if (top == "asset") {
        t.kind = TargetKind::Asset;
        return 1;
    }
    if (top == "extensionsUsed" || top == "extensionsRequired") {
        const auto& names = top == "extensionsUsed" ? s.extensions_used : s.extensions_required;
        const auto i = tok.size() > 1 ? array_index(tok[1]) : std::nullopt;
        if (!i || !in(*i, names.size())) return 0;
        t.kind = TargetKind::Extension;
        t.index = *i;
        for (std::size_t m = 0; m < s.materials.size(); ++m) {
            const auto& used = s.materials[m].extensions;
            if (std::find(used.begin(), used.end(), names[static_cast<std::size_t>(*i)]) !=
                used.end()) {
                t.material = static_cast<std::int32_t>(m);
                break;
            }
        }
        return 2;
    }
    if (top == "extensions") { // /extensions/KHR_lights_punctual/lights/N
        if (tok.size() < 4 || tok[1] != "KHR_lights_punctual" || tok[2] != "lights") return 0;
        const auto i = array_index(tok[3]);
        if (!i || !in(*i, s.lights.size())) return 0;
        t.kind = TargetKind::Light;
        t.index = *i;
        t.node = node_with(s, &Node::light, *i);
        return 4;
    }
    const auto i = tok.size() > 1 ? array_index(tok[1]) : std::nullopt;
    if (!i) return 0;
    t.index = *i;
    if (top == "scenes") {
        if (!in(*i, s.scenes.size())) return 0;
        t.kind = TargetKind::Scene;
    } else if (top == "nodes") {
        if (!in(*i, s.nodes.size())) return 0;
        t.kind = TargetKind::Node;
        t.node = *i;
    } else if (top == "meshes") {
        if (!in(*i, s.mesh_primitives.size())) return 0;
        const auto& prims = s.mesh_primitives[static_cast<std::size_t>(*i)];
        if (tok.size() > 3 && tok[2] == "primitives") {
            const auto p = array_index(tok[3]);
            if (p && in(*p, prims.size())) {
                t.sub = *p;
                resolve_primitive(s, t);
                return 4;
            }
        }
        t.kind = TargetKind::Mesh;
        for (const std::int32_t m : prims)
            if (m >= 0) {
                t.engine_mesh = m;
                t.node = node_of_mesh(s, m);
                break;
            }
        if (t.node < 0) t.node = node_with(s, &Node::mesh, *i);
    } else if (top == "materials") {
        if (!in(*i, s.materials.size()) ||
            s.materials[static_cast<std::size_t>(*i)].gltf_index != *i)
            return 0;
        t.kind = TargetKind::Material;
        t.material = *i;
        for (std::size_t m = 0; m < s.meshes.size() && t.engine_mesh < 0; ++m)
            if (static_cast<std::int32_t>(s.meshes[m].material_id) == *i &&
                node_of_mesh(s, static_cast<std::int32_t>(m)) >= 0) {
                t.engine_mesh = static_cast<std::int32_t>(m);
                t.node = node_of_mesh(s, t.engine_mesh);
            }
    } else if (top == "textures") {
        if (!in(*i, s.textures.size())) return 0;
        t.kind = TargetKind::Texture;
        t.texture = *i;
        t.image = s.textures[static_cast<std::size_t>(*i)].image;
    } else if (top == "images") {
        if (!in(*i, s.images.size())) return 0;
        t.kind = TargetKind::Image;
        t.image = *i;
        for (std::size_t x = 0; x < s.textures.size(); ++x)
            if (s.textures[x].image == *i) {
                t.texture = static_cast<std::int32_t>(x);
                break;
            }
    } else if (top == "samplers") {
        if (!in(*i, s.samplers.size())) return 0;
        t.kind = TargetKind::Sampler;
    } else if (top == "accessors") {
        // The scene keeps no accessor table; an index the file has not is only known
        // by nobody reading it, so any index resolves (with no uses).
        t.kind = TargetKind::Accessor;
        for_each_accessor_use(s, [&](std::int32_t a, std::int32_t mesh, std::string attribute) {
            if (a == *i) t.uses.push_back({mesh, std::move(attribute)});
        });
        if (!t.uses.empty()) {
            t.engine_mesh = t.uses.front().engine_mesh;
            t.node = node_of_mesh(s, t.engine_mesh);
            t.material = static_cast<std::int32_t>(
                s.meshes[static_cast<std::size_t>(t.engine_mesh)].material_id);
        }
    } else if (top == "bufferViews") {
        t.kind = TargetKind::BufferView;
    } else if (top == "buffers") {
        t.kind = TargetKind::Buffer;
    } else if (top == "cameras") {
        if (!in(*i, s.cameras.size())) return 0;
        t.kind = TargetKind::Camera;
        t.node = node_with(s, &Node::camera, *i);
    } else if (top == "skins") {
        if (!in(*i, s.skins.size())) return 0;
        const Skin& skin = s.skins[static_cast<std::size_t>(*i)];
        if (tok.size() > 3 && tok[2] == "joints") {
            const auto j = array_index(tok[3]);
            if (j && in(*j, skin.joints.size())) {
                t.kind = TargetKind::SkinJoint;
                t.sub = *j;
                t.node = static_cast<std::int32_t>(skin.joints[static_cast<std::size_t>(*j)]);
                return 4;
            }
        }
        t.kind = TargetKind::Skin;
        t.node = node_with(s, &Node::skin, *i);
    } else if (top == "animations") {
        if (!in(*i, s.animations.size())) return 0;
        const Animation& anim = s.animations[static_cast<std::size_t>(*i)];
        t.kind = TargetKind::Animation;
        if (tok.size() > 3 && (tok[2] == "channels" || tok[2] == "samplers")) {
            const auto c = array_index(tok[3]);
            const bool channel = tok[2] == "channels";
            for (std::size_t k = 0; c && k < anim.channels.size(); ++k) {
                const AnimationChannel& ch = anim.channels[k];
                if (static_cast<std::int32_t>(channel ? ch.source : ch.source_sampler) != *c)
                    continue;
                t.kind = channel ? TargetKind::AnimationChannel : TargetKind::AnimationSampler;
                t.sub = static_cast<std::int32_t>(channel ? k : ch.sampler);
                t.node = static_cast<std::int32_t>(ch.node);
                return 4;
            }
        }
    } else {
        return 0;
    }
    return 2;
}

} // namespace

std::string_view to_string(TargetKind kind) {
    switch (kind) {
    case TargetKind::None:
        return "none";
    case TargetKind::Asset:
        return "asset";
    case TargetKind::Scene:
        return "scene";
    case TargetKind::Node:
        return "node";
    case TargetKind::Mesh:
        return "mesh";
    case TargetKind::Primitive:
        return "primitive";
    case TargetKind::Material:
        return "material";
    case TargetKind::Texture:
        return "texture";
    case TargetKind::Image:
        return "image";
    case TargetKind::Sampler:
        return "sampler";
    case TargetKind::Accessor:
        return "accessor";
    case TargetKind::BufferView:
        return "bufferView";
    case TargetKind::Buffer:
        return "buffer";
    case TargetKind::Animation:
        return "animation";
    case TargetKind::AnimationChannel:
        return "animation channel";
    case TargetKind::AnimationSampler:
        return "animation sampler";
    case TargetKind::Skin:
        return "skin";
    case TargetKind::SkinJoint:
        return "skin joint";
    case TargetKind::Camera:
        return "camera";
    case TargetKind::Light:
        return "light";
    case TargetKind::Extension:
        return "extension";
    }
    return "none";
}

std::string json_pointer_token(std::string_view name) {
    std::string out;
    for (const char c : name) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

PointerTarget resolve_pointer(const Scene& scene, std::string_view pointer) {
    PointerTarget t;
    const auto tokens = split_pointer(pointer);
    if (!tokens) return t;
    const std::size_t used = resolve_tokens(scene, *tokens, t);
    if (used == 0) return PointerTarget{};
    t.rest = join_rest(*tokens, used);
    return t;
}

ObjectMarks mark_objects(const Scene& scene, const std::vector<ValidationMessage>& messages) {
    ObjectMarks marks;
    marks.nodes.assign(scene.nodes.size(), -1);
    marks.engine_meshes.assign(scene.meshes.size(), -1);
    marks.materials.assign(scene.materials.size(), -1);
    marks.textures.assign(scene.textures.size(), -1);
    marks.animations.assign(scene.animations.size(), -1);
    marks.skins.assign(scene.skins.size(), -1);
    auto mark = [](std::vector<int>& v, std::int32_t i, Severity s) {
        if (!in(i, v.size())) return;
        int& m = v[static_cast<std::size_t>(i)];
        if (m < 0 || static_cast<int>(s) < m) m = static_cast<int>(s);
    };
    // Accessor readers once (resolve_pointer scans the meshes per call).
    std::vector<std::vector<std::int32_t>> readers;
    for_each_accessor_use(scene, [&](std::int32_t a, std::int32_t mesh, const std::string&) {
        if (static_cast<std::size_t>(a) >= readers.size()) readers.resize(std::size_t(a) + 1);
        readers[static_cast<std::size_t>(a)].push_back(mesh);
    });
    for (const ValidationMessage& msg : messages) {
        const auto tokens = split_pointer(msg.pointer);
        if (!tokens || tokens->size() < 2) continue;
        if ((*tokens)[0] == "accessors") { // without resolve_pointer's scan
            const auto a = array_index((*tokens)[1]);
            if (a && in(*a, readers.size()))
                for (const std::int32_t m : readers[static_cast<std::size_t>(*a)])
                    mark(marks.engine_meshes, m, msg.severity);
            continue;
        }
        PointerTarget t;
        if (resolve_tokens(scene, *tokens, t) == 0) continue;
        switch (t.kind) {
        case TargetKind::Node:
        case TargetKind::SkinJoint:
        case TargetKind::Camera:
        case TargetKind::Light:
            mark(marks.nodes, t.node, msg.severity);
            break;
        case TargetKind::Primitive:
            mark(marks.engine_meshes, t.engine_mesh, msg.severity);
            break;
        case TargetKind::Mesh:
            for (const std::int32_t m : scene.mesh_primitives[static_cast<std::size_t>(t.index)])
                mark(marks.engine_meshes, m, msg.severity);
            break;
        case TargetKind::Material:
            mark(marks.materials, t.material, msg.severity);
            break;
        case TargetKind::Texture:
            mark(marks.textures, t.texture, msg.severity);
            break;
        case TargetKind::Image:
            for (std::size_t x = 0; x < scene.textures.size(); ++x)
                if (scene.textures[x].image == t.image)
                    mark(marks.textures, static_cast<std::int32_t>(x), msg.severity);
            break;
        case TargetKind::Animation:
        case TargetKind::AnimationChannel:
        case TargetKind::AnimationSampler:
            mark(marks.animations, t.index, msg.severity);
            if (t.kind == TargetKind::AnimationChannel) mark(marks.nodes, t.node, msg.severity);
            break;
        case TargetKind::Skin:
            mark(marks.skins, t.index, msg.severity);
            break;
        default:
            break;
        }
        if (t.kind == TargetKind::SkinJoint) mark(marks.skins, t.index, msg.severity);
    }
    return marks;
}

std::int64_t element_index_in_message(std::string_view message) {
    constexpr std::string_view key = "at index ";
    const std::size_t at = message.find(key);
    if (at == std::string_view::npos) return -1;
    const char* begin = message.data() + at + key.size();
    const char* end = message.data() + message.size();
    if (begin < end && *begin == '`') ++begin; // ISSUES.md quotes arguments
    std::int64_t v = -1;
    const auto [p, ec] = std::from_chars(begin, end, v);
    return ec == std::errc() && v >= 0 ? v : -1;
}

} // namespace sherpa::scene
