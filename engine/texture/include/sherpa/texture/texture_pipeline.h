#pragma once
// The texture pipeline over a Scene: find the (image, role) pairs the displayed
// scene's materials use, load each from the KTX2 cache or decode, mip and
// compress it, and hand back CPU-side prepared textures (levels + Vulkan format)
// for the GPU layer to upload, with the inspection data the texture dock shows.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/core/progress.h>
#include <sherpa/scene/scene.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>
#include <sherpa/texture/luminance_grid.h>
#include <sherpa/texture/texture_cache.h>

namespace sherpa::tex {

// Bumped whenever encoder, decoder or mip output changes, so old cache files stop
// matching. 3: sources are decoded with unassociated alpha (2 stored premultiplied
// colour for every RGBA PNG).
inline constexpr int kTextureEncoderVersion = 3;

// One image in one role, as used by the displayed scene's materials.
struct TextureUse {
    std::int32_t image = -1;
    scene::TextureRole role = scene::kRoleColor; // exactly one role bit
    std::vector<std::int32_t> textures;          // glTF texture indices that reach it in this role
    // Set when alpha-masked materials use it as base colour, all with this cutoff
    // (mips then keep its alpha coverage); unset when their cutoffs differ.
    std::optional<float> alpha_cutoff;
};

// Unique (image, role) pairs over the materials of scene.instances, deduplicated
// by image (two textures sharing an image share one use), in image order.
std::vector<TextureUse> collect_texture_uses(const scene::Scene& scene);

struct PipelineOptions {
    std::optional<std::filesystem::path> cache_dir; // nullopt: no cache at all
    std::uint64_t cache_cap_bytes = kDefaultCacheCapBytes;
    int bc7_level = kBc7DefaultLevel;
    int bc5_level = kBc5DefaultLevel;
    bool device_supports_bc = true; // false: RGBA8 fallback
    int decode_threads = 2;         // OIIO gains nothing from threads within one file
    // How long to wait for another process (or thread) making the same cache entry
    // before making it here too.
    std::chrono::milliseconds cache_lock_timeout{std::chrono::minutes(2)};
    core::SimdLevel simd = core::best_simd_level();
    // Textures ready of textures to prepare (cache hits count at once, misses as
    // each is compressed); called on the calling thread.
    core::ProgressCallback progress;
    // Polled before each decode and each compression: a cancelled run returns a
    // set with `cancelled` set and no textures (cache files already written stay:
    // they are complete entries).
    const core::CancelToken* cancel = nullptr;
};

// Missing: the image's file could not be read (or its bufferView is empty);
// Undecodable: it has bytes the decoder refuses. Both leave the texture `failed`.
enum class CacheState : std::uint8_t {
    Hit,
    Miss,
    Stale,
    Recompressed,
    Fallback,
    Missing,
    Undecodable
};
// hit, miss, stale, recompressed, fallback, missing, undecodable
std::string_view to_string(CacheState state);
std::string_view role_name(scene::TextureRole role); // color, linear, normal

struct PreparedTexture {
    std::int32_t image = -1;
    std::string source; // URI, "bufferView N" or "generated"
    scene::TextureRole role = scene::kRoleColor;
    std::vector<std::int32_t> textures;
    VkFormat format = VkFormat::Undefined;
    std::uint32_t width = 0, height = 0;
    std::vector<std::vector<std::uint8_t>> levels; // [0] full size; upload as is
    Hash128 source_hash;
    std::string recipe;
    CacheState state = CacheState::Miss;
    std::filesystem::path cache_file; // empty without a cache
    std::uint64_t bytes_on_disk = 0;  // the KTX2 file (0 without a cache)
    std::uint64_t bytes_gpu = 0;      // all levels
    double decode_ms = 0, mip_ms = 0, encode_ms = 0;
    std::optional<double> psnr;    // level 0 against the decoded source; none for RGBA8
    std::string note;              // why stale / recompressed / undecodable, or a write failure
    bool failed = false;           // state Missing or Undecodable: no levels
    std::string location;          // the image's file path, else "bufferView N", "data URI"...
    std::vector<std::string> uses; // "material 'NAME' baseColorTexture, ..." (image_slot_uses)
    // An image an emitting material's emissiveTexture reads: its luminance grid, made from
    // the decoded source (a miss) or read from the cache entry (a hit on an entry that
    // holds one); the path tracer's light list reads it instead of decoding the image
    // again. Null otherwise.
    std::shared_ptr<const LuminanceGrid> luminance;
};

struct PreparedTextureSet {
    std::vector<PreparedTexture> textures;
    std::vector<std::string> warnings; // fallbacks, decode failures, cache write failures
    // What the user need not act on (how textures were stored for the device): for
    // reports and logs at info level, not printed as warnings.
    std::vector<std::string> notices;
    bool cancelled = false; // PipelineOptions::cancel stopped it: no textures

    // Index into `textures` for glTF texture `texture` used in `role`, or -1.
    std::int32_t find(std::int32_t texture, scene::TextureRole role) const;
};

// Recipe text for one use: everything besides the source that shapes the output.
std::string texture_recipe(const TextureUse& use, const PipelineOptions& options);

PreparedTextureSet prepare_textures(const scene::Scene& scene, const PipelineOptions& options);

// An image that cannot become a texture, without running the pipeline: its bytes
// are missing, or the decoder refuses its header.
struct ImageProblem {
    std::int32_t image = -1;
    CacheState state = CacheState::Missing; // Missing or Undecodable
    std::string location;                   // image_location(): the file path, ...
    std::string reason;                     // the decoder's words (Undecodable)
    std::vector<std::string> uses;          // image_slot_uses()
};
// "missing: FILE (used by material 'M' baseColorTexture, occlusionTexture)", or
// "undecodable: FILE (used by ...): REASON"; one line.
std::string describe(const ImageProblem& problem);
// Every image of `scene` (used or not) that is missing or whose header does not
// decode, in image order.
std::vector<ImageProblem> find_image_problems(const scene::Scene& scene);

// For the GPU layer once it has uploaded set.textures[i] to bindless slot
// bindless_slot[i]: the material's GPU record with every texture field resolved to
// its slot, or kTextureSentinel where the slot has no texture or its texture
// failed (the GPU layer then binds its default texture).
scene::GPUMaterialData resolve_material(const scene::MaterialInstance& material,
                                        const PreparedTextureSet& set,
                                        std::span<const std::uint32_t> bindless_slot);

} // namespace sherpa::tex
