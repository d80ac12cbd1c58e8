// prepare_textures: cache lookups, then decoding (a few files at a time),
// mip generation and block compression of the misses, then cache writes.
#include <sherpa/texture/basis.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <new>
#include <thread>

#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/image.h>
#include <sherpa/texture/mips.h>
#include <sherpa/texture/quality.h>
#include <sherpa/texture/source_export.h>

namespace sherpa::tex {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

VkFormat output_format(scene::TextureRole role, bool bc) {
    if (!bc) return role == scene::kRoleColor ? VkFormat::R8G8B8A8Srgb : VkFormat::R8G8B8A8Unorm;
    return role == scene::kRoleColor    ? VkFormat::Bc7SrgbBlock
           : role == scene::kRoleNormal ? VkFormat::Bc5UnormBlock
                                        : VkFormat::Bc7UnormBlock;
}

MipFilter mip_filter(scene::TextureRole role) {
    return role == scene::kRoleColor    ? MipFilter::Color
           : role == scene::kRoleNormal ? MipFilter::Normal
                                        : MipFilter::Linear;
}

std::string source_name(const scene::ImageRecord& img, std::int32_t index) {
    if (!img.uri.empty()) return img.uri;
    if (img.buffer_view >= 0) return "bufferView " + std::to_string(img.buffer_view);
    if (!img.pixels.empty()) return "generated";
    return "image " + std::to_string(index);
}

Hash128 source_hash(const scene::ImageRecord& img) {
    if (!img.encoded.empty()) return hash_bytes(img.encoded);
    // Generated images have no encoded form; their size is part of their identity.
    std::vector<std::uint8_t> bytes(img.pixels);
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(img.width >> (8 * i)));
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<std::uint8_t>(img.height >> (8 * i)));
    return hash_bytes(bytes);
}

// PSNR of level 0 over the channels the role's shader reads.
double measure_psnr(scene::TextureRole role, const RgbaImage& source,
                    const std::vector<std::uint8_t>& blocks, VkFormat format) {
    const BlockFormat bf = format == VkFormat::Bc5UnormBlock ? BlockFormat::Bc5 : BlockFormat::Bc7;
    const auto decoded = decode_image(bf, blocks, source.width, source.height);
    const unsigned channels = role == scene::kRoleNormal ? kChannelsRg
                              : source.has_alpha()       ? kChannelsRgba
                                                         : kChannelsRgb;
    return squared_error(source.pixels, decoded, channels).psnr();
}

// Decodes, mips and compresses one texture whose source is already decoded.
void compress(PreparedTexture& t, const TextureUse& use, const RgbaImage& source,
              const PipelineOptions& opt) {
    auto start = std::chrono::steady_clock::now();
    const auto chain = build_mip_chain(source, {mip_filter(use.role), use.alpha_cutoff});
    t.mip_ms = ms_since(start);
    start = std::chrono::steady_clock::now();
    t.levels.clear();
    for (const RgbaImage& level : chain) {
        if (!is_block_compressed(t.format)) {
            t.levels.push_back(level.pixels);
            continue;
        }
        const bool bc5 = t.format == VkFormat::Bc5UnormBlock;
        const EncodeSettings settings{bc5 ? opt.bc5_level : opt.bc7_level, opt.simd};
        t.levels.push_back(encode_image(bc5 ? BlockFormat::Bc5 : BlockFormat::Bc7, level.pixels,
                                        level.width, level.height, settings));
    }
    t.encode_ms = ms_since(start);
    if (is_block_compressed(t.format))
        t.psnr = measure_psnr(use.role, source, t.levels[0], t.format);
}

// One warning per image, not per role it is used in.
void add_once(std::vector<std::string>& warnings, std::string warning) {
    if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end())
        warnings.push_back(std::move(warning));
}

// A warning for a texture whose image failed (t.state Missing or Undecodable).
std::string failure_warning(const PreparedTexture& t, std::string reason) {
    return "texture " +
           describe(ImageProblem{t.image, t.state, t.location, std::move(reason), t.uses});
}

// decode_encoded_image names the image by its decoder hint ("image.png: ..."); the
// warning names the file already.
std::string without_hint(const scene::ImageRecord& img, const std::string& error) {
    const std::string prefix = image_decoder_hint(img) + ": ";
    return error.starts_with(prefix) ? error.substr(prefix.size()) : error;
}

// Takes a cache hit's levels and inspection data.
void use_hit(PreparedTexture& t, CacheLookup& found, const PipelineOptions& opt) {
    t.state = opt.device_supports_bc ? CacheState::Hit : CacheState::Fallback;
    t.width = found.texture.width, t.height = found.texture.height;
    t.levels = std::move(found.texture.levels);
    t.bytes_on_disk = found.file_bytes;
    if (const std::string* p = found.texture.find(kKeyPsnr))
        t.psnr = std::strtod(p->c_str(), nullptr);
    LuminanceGrid grid;
    if (const std::string* g = found.texture.find(kKeyLuminance);
        g && decode_luminance_grid(*g, grid))
        t.luminance = std::make_shared<const LuminanceGrid>(std::move(grid));
}

// Per image: whether a material that emits (a factor above 0, not unlit) reads it as
// its emissiveTexture; those images' luminance grids are made while they are decoded.
std::vector<bool> emissive_images(const scene::Scene& scene) {
    std::vector<bool> out(scene.images.size(), false);
    for (const scene::MaterialInstance& m : scene.materials) {
        const glm::vec3 e = m.emissive_factor * m.emissive_strength;
        if (m.unlit || !(e.r > 0.0f || e.g > 0.0f || e.b > 0.0f) || !m.emissive.present() ||
            std::size_t(m.emissive.texture) >= scene.textures.size())
            continue;
        const std::int32_t image = scene.textures[std::size_t(m.emissive.texture)].image;
        if (image >= 0 && std::size_t(image) < out.size()) out[std::size_t(image)] = true;
    }
    return out;
}

} // namespace

std::string texture_recipe(const TextureUse& use, const PipelineOptions& opt) {
    const VkFormat format = output_format(use.role, opt.device_supports_bc);
    std::string r = "sherpa-texture/" + std::to_string(kTextureEncoderVersion);
    r += ";format=" + std::string(vk_format_name(format));
    if (format == VkFormat::Bc7SrgbBlock || format == VkFormat::Bc7UnormBlock)
        r += ";bc7-level=" + std::to_string(opt.bc7_level);
    if (format == VkFormat::Bc5UnormBlock) r += ";bc5-level=" + std::to_string(opt.bc5_level);
    r += ";mips=full-box;filter=" + std::string(role_name(use.role));
    if (use.alpha_cutoff) {
        char buf[32];
        std::snprintf(buf, sizeof buf, ";coverage=%.4f", *use.alpha_cutoff);
        r += buf;
    }
    return r;
}

std::string describe(const ImageProblem& p) {
    std::string s = std::string(to_string(p.state)) + ": " + p.location;
    for (std::size_t i = 0; i < p.uses.size(); ++i) s += (i == 0 ? " (used by " : "; ") + p.uses[i];
    s += p.uses.empty() ? " (used by no material)" : ")";
    if (!p.reason.empty()) s += ": " + p.reason;
    return s;
}

std::vector<ImageProblem> find_image_problems(const scene::Scene& scene) {
    std::vector<ImageProblem> problems;
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const scene::ImageRecord& img = scene.images[i];
        const auto index = static_cast<std::int32_t>(i);
        ImageProblem p{index,
                       CacheState::Missing,
                       scene::image_location(scene, index),
                       {},
                       scene::image_slot_uses(scene, index)};
        if (!scene::image_is_missing(img)) {
            // Headers only: OpenImageIO reads no KTX2, whose header, level index and
            // global data ranges are checked here; the rest are probed. Both check the
            // size against the texel budget, so nothing here inflates or decodes.
            if (img.encoded.empty() ||
                (is_ktx2(img.encoded)
                     ? probe_ktx2_basis(img.encoded, p.reason)
                     : probe_encoded_image(img.encoded, image_decoder_hint(img), p.reason)))
                continue;
            p.reason = without_hint(img, p.reason); // the location names the file
            p.state = CacheState::Undecodable;
        }
        problems.push_back(std::move(p));
    }
    return problems;
}

PreparedTextureSet prepare_textures(const scene::Scene& scene, const PipelineOptions& opt) {
    PreparedTextureSet set;
    const std::vector<TextureUse> uses = collect_texture_uses(scene);
    const std::vector<bool> emissive = emissive_images(scene);
    std::optional<TextureCache> cache;
    if (opt.cache_dir) {
        cache.emplace(*opt.cache_dir, opt.cache_cap_bytes);
        // Without this, every entry's lock fails and reads as another process's.
        if (const std::string problem = cache->directory_problem(); !problem.empty()) {
            set.warnings.push_back("texture cache: " + problem +
                                   "; textures are made without the cache");
            cache.reset();
        }
    }
    if (!opt.device_supports_bc && !uses.empty())
        set.warnings.push_back(
            "device cannot sample BC formats: textures fall back to uncompressed RGBA8");

    std::vector<std::size_t> misses; // indices into set.textures still to be made
    for (const TextureUse& use : uses) {
        const scene::ImageRecord& img = scene.images[std::size_t(use.image)];
        PreparedTexture t;
        t.image = use.image, t.role = use.role, t.textures = use.textures;
        t.source = source_name(img, use.image);
        t.format = output_format(use.role, opt.device_supports_bc);
        t.source_hash = source_hash(img);
        t.recipe = texture_recipe(use, opt);
        t.location = scene::image_location(scene, use.image);
        t.uses = scene::image_slot_uses(scene, use.image);
        const Hash128 key = cache_key(t.source_hash, t.recipe);
        t.state = CacheState::Miss;
        if (scene::image_is_missing(img)) {
            // Nothing to look up or decode: say what is missing and who reads it.
            t.state = CacheState::Missing;
            t.failed = true;
            t.note = "missing: " + t.location;
            if (const std::string why = scene::image_missing_reason(scene, img); !why.empty())
                t.note += " (" + why + ")";
            add_once(set.warnings, failure_warning(t, {}));
            set.textures.push_back(std::move(t));
            continue;
        }
        if (cache) {
            t.cache_file = cache->file_for(key);
            CacheLookup found = cache->load(key, t.source_hash, t.recipe);
            if (found.state == LookupState::Hit) {
                use_hit(t, found, opt);
            } else if (found.state == LookupState::Stale || found.state == LookupState::Corrupt) {
                t.state = found.state == LookupState::Stale ? CacheState::Stale
                                                            : CacheState::Recompressed;
                t.note = found.problem;
                set.warnings.push_back("texture cache: " + found.problem + "; recompressing");
            }
        }
        if (t.levels.empty()) misses.push_back(set.textures.size());
        set.textures.push_back(std::move(t));
    }

    std::size_t ready = set.textures.size() - misses.size();
    auto report = [&] {
        if (opt.progress) opt.progress(ready, set.textures.size());
    };
    auto stop = [&set] {
        set = {};
        set.cancelled = true;
        return std::move(set);
    };
    report();
    if (core::is_cancelled(opt.cancel)) return stop();

    // Decode the misses, a few files at a time (OpenImageIO decodes one file on one thread).
    std::vector<RgbaImage> decoded(misses.size());
    std::vector<std::string> errors(misses.size());
    std::atomic<std::size_t> next{0};
    auto decode_worker = [&] {
        for (std::size_t i; (i = next++) < misses.size();) {
            if (core::is_cancelled(opt.cancel)) return;
            PreparedTexture& t = set.textures[misses[i]];
            const auto start = std::chrono::steady_clock::now();
            // Nothing may escape a worker thread (std::terminate): a failure is this
            // image's error, and the other images go on.
            try {
                if (!decode_image_source(scene.images[std::size_t(t.image)], decoded[i], errors[i]))
                    decoded[i] = {};
            } catch (const std::bad_alloc&) {
                decoded[i] = {};
                errors[i] = "out of memory while decoding";
            } catch (const std::exception& e) {
                decoded[i] = {};
                errors[i] = std::string("decoder failed: ") + e.what();
            }
            t.decode_ms = ms_since(start);
        }
    };
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(1, opt.decode_threads) && std::size_t(w) < misses.size(); ++w)
        workers.emplace_back(decode_worker);
    for (auto& w : workers) w.join();
    if (core::is_cancelled(opt.cancel)) return stop();

    // Compress (OpenMP across blocks inside encode_image), then store.
    for (std::size_t i = 0; i < misses.size(); ++i, ++ready, report()) {
        if (core::is_cancelled(opt.cancel)) return stop();
        PreparedTexture& t = set.textures[misses[i]];
        if (decoded[i].empty()) {
            t.failed = true;
            t.state = CacheState::Undecodable;
            const std::string reason = without_hint(scene.images[std::size_t(t.image)], errors[i]);
            t.note = "undecodable: " + reason;
            add_once(set.warnings, failure_warning(t, reason));
            continue;
        }
        const Hash128 key = cache_key(t.source_hash, t.recipe);
        EntryLock lock; // held until this entry is stored
        if (cache) {
            // Another process making the same entry holds its lock: wait, then reuse.
            lock = cache->lock_entry(key, opt.cache_lock_timeout);
            if (!lock.held())
                set.warnings.push_back("texture cache: " + t.cache_file.string() +
                                       ": another process is still making it; making it here too");
            CacheLookup found = cache->load(key, t.source_hash, t.recipe);
            if (found.state == LookupState::Hit) {
                use_hit(t, found, opt);
                t.note = "made by another process while this one waited";
                decoded[i] = {};
                continue;
            }
        }
        const TextureUse& use = uses[misses[i]];
        t.width = decoded[i].width, t.height = decoded[i].height;
        try {
            compress(t, use, decoded[i], opt);
        } catch (const std::bad_alloc&) { // within the texel budget, not within this memory
            decoded[i] = {};
            t.levels.clear();
            t.failed = true;
            t.state = CacheState::Undecodable;
            const std::string reason = "out of memory while making the mip chain and blocks of " +
                                       std::to_string(t.width) + "x" + std::to_string(t.height);
            t.note = "undecodable: " + reason;
            add_once(set.warnings, failure_warning(t, reason));
            continue;
        }
        if (emissive[std::size_t(t.image)])
            t.luminance = std::make_shared<const LuminanceGrid>(
                luminance_grid(decoded[i].width, decoded[i].height, decoded[i].pixels));
        decoded[i] = {}; // release the pixels early: scenes can hold many large images
        if (!opt.device_supports_bc) t.state = CacheState::Fallback;
        if (!cache) continue;
        Ktx2Texture ktx{t.format, t.width, t.height, t.levels, {}};
        // "inf" for lossless levels; strtod reads it back.
        if (t.psnr) ktx.metadata.emplace_back(std::string(kKeyPsnr), std::to_string(*t.psnr));
        if (t.luminance)
            ktx.metadata.emplace_back(std::string(kKeyLuminance),
                                      encode_luminance_grid(*t.luminance));
        std::string error;
        if (!cache->store(key, t.source_hash, t.recipe, std::move(ktx), error)) {
            t.note = error;
            set.warnings.push_back("texture cache: " + error);
        }
    }
    for (PreparedTexture& t : set.textures) {
        for (const auto& level : t.levels) t.bytes_gpu += level.size();
        // Only a regular file has a size on disk; a directory or FIFO where the entry
        // belongs was reported by the lookup and the failed store (it stays 0 then).
        std::error_code ec;
        if (!t.cache_file.empty() && t.bytes_on_disk == 0 &&
            std::filesystem::is_regular_file(t.cache_file, ec)) {
            const std::uintmax_t size = std::filesystem::file_size(t.cache_file, ec);
            if (!ec) t.bytes_on_disk = size;
        }
    }
    return set;
}

} // namespace sherpa::tex
