// Texture cache against what a real cache directory holds besides good entries:
// edited metadata, a directory or FIFO where an entry belongs, temp files of killed
// writers, and a second process making the same entry (issue #12).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <future>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/texture_pipeline.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;
namespace fs = std::filesystem;

namespace {

// One generated base-colour image on one instance: one cache entry.
scene::Scene one_texture_scene() {
    scene::Scene s;
    scene::ImageRecord img;
    const RgbaImage pixels = test::synthetic_image(16, 12, false, 7);
    img.name = "generated", img.width = pixels.width, img.height = pixels.height;
    img.pixels = pixels.pixels;
    s.images.push_back(img);
    s.textures = {{"t0", 0, -1, scene::kRoleColor}};
    scene::MaterialInstance m;
    m.base_color.texture = 0;
    s.materials = {m};
    s.instances.resize(1);
    s.instances[0].material_id = 0;
    return s;
}

void write_bytes(const fs::path& path, std::size_t n) {
    std::ofstream(path, std::ios::binary) << std::string(n, 'x');
}

bool any_warning_has(const PreparedTextureSet& set, const std::string& a, const std::string& b) {
    for (const auto& w : set.warnings)
        if (w.find(a) != std::string::npos && w.find(b) != std::string::npos) return true;
    return false;
}

// The path of the scene's one cache entry in `dir`, made and then removed, so the
// test can put something else there.
fs::path vacated_entry(const scene::Scene& scene, const fs::path& dir) {
    const fs::path entry =
        prepare_textures(scene, test::cache_test_options(dir)).textures[0].cache_file;
    fs::remove(entry);
    return entry;
}

// A PID that belonged to a process that has exited.
pid_t dead_pid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

} // namespace

TEST(CacheRobustness, EditedPsnrIsNotServedAsHit) {
    const auto dir = test::fresh_temp_dir("cache-psnr");
    const scene::Scene scene = one_texture_scene();
    const auto first = prepare_textures(scene, test::cache_test_options(dir));
    ASSERT_EQ(first.textures.size(), 1u);
    ASSERT_TRUE(first.textures[0].psnr.has_value());
    // Change the first digit of the stored PSNR in place (same length, valid KTX2).
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(core::read_file(first.textures[0].cache_file, bytes, error)) << error;
    const std::string key(kKeyPsnr);
    const auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
    ASSERT_NE(at, bytes.end());
    auto digit = at + std::ptrdiff_t(key.size()) + 1; // past the key's NUL
    *digit = *digit == '9' ? '1' : '9';
    ASSERT_TRUE(core::write_file_atomic(first.textures[0].cache_file, bytes, error)) << error;

    const auto second = prepare_textures(scene, test::cache_test_options(dir));
    EXPECT_EQ(second.textures[0].state, CacheState::Recompressed);
    EXPECT_NEAR(*second.textures[0].psnr, *first.textures[0].psnr, 1e-3);
    fs::remove_all(dir);
}

TEST(CacheRobustness, DirectoryAtEntryPathIsReportedNotSized) {
    const auto dir = test::fresh_temp_dir("cache-dir-entry");
    const scene::Scene scene = one_texture_scene();
    const fs::path entry = vacated_entry(scene, dir);
    fs::create_directory(entry);
    const auto set = prepare_textures(scene, test::cache_test_options(dir));
    const PreparedTexture& t = set.textures[0];
    EXPECT_EQ(t.state, CacheState::Recompressed);
    EXPECT_FALSE(t.levels.empty()); // the texture is still made
    EXPECT_EQ(t.bytes_on_disk, 0u); // not (uintmax_t)-1 from a failed file_size
    EXPECT_TRUE(any_warning_has(set, entry.string(), "directory"));
    fs::remove_all(dir);
}

TEST(CacheRobustness, FifoAtEntryPathIsRefusedWithoutBlocking) {
    const auto dir = test::fresh_temp_dir("cache-fifo-entry");
    const scene::Scene scene = one_texture_scene();
    const fs::path entry = vacated_entry(scene, dir);
    ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
    // Run where a blocked open cannot take the test binary with it; a hang is a
    // failure here, whatever the time limit CTest would apply.
    auto done = std::make_shared<std::promise<PreparedTextureSet>>();
    auto result = done->get_future();
    std::thread([done, scene, dir] {
        done->set_value(prepare_textures(scene, test::cache_test_options(dir)));
    }).detach();
    ASSERT_EQ(result.wait_for(std::chrono::seconds(60)), std::future_status::ready)
        << "prepare_textures blocked on the FIFO at " << entry;
    const auto set = result.get();
    EXPECT_EQ(set.textures[0].state, CacheState::Recompressed);
    EXPECT_TRUE(any_warning_has(set, entry.string(), "not a regular file"));
    fs::remove_all(dir);
}

TEST(CacheRobustness, TempFilesOfDeadWritersAreRemoved) {
    const auto dir = test::fresh_temp_dir("cache-tmp-dead");
    const auto two_minutes_ago = fs::file_time_type::clock::now() - std::chrono::minutes(2);
    const fs::path dead = dir / ("a.ktx2.tmp." + std::to_string(dead_pid()) + ".Ab12Cd");
    const fs::path live = dir / ("b.ktx2.tmp." + std::to_string(::getpid()) + ".Ab12Cd");
    const fs::path fresh_dead = dir / ("c.ktx2.tmp." + std::to_string(dead_pid()) + ".Ab12Cd");
    for (const auto& p : {dead, live, fresh_dead}) write_bytes(p, 10);
    fs::last_write_time(dead, two_minutes_ago);
    fs::last_write_time(live, two_minutes_ago);
    TextureCache(dir).evict();
    EXPECT_FALSE(fs::exists(dead));      // its writer is gone
    EXPECT_TRUE(fs::exists(live));       // this process could still be writing it
    EXPECT_TRUE(fs::exists(fresh_dead)); // too new to judge (another PID namespace?)
    fs::remove_all(dir);
}

TEST(CacheRobustness, LiveTempFilesCountAgainstCap) {
    const auto dir = test::fresh_temp_dir("cache-tmp-cap");
    write_bytes(dir / "00000000000000000000000000000001.ktx2", 1000);
    write_bytes(dir / ("x.ktx2.tmp." + std::to_string(::getpid()) + ".Ab12Cd"), 2500);
    EXPECT_EQ(TextureCache(dir, 3000).evict(), 1u); // 3500 bytes in all: over the cap
    fs::remove_all(dir);
}

TEST(CacheRobustness, SecondMakerWaitsForFirstAndReusesItsEntry) {
    const auto dir = test::fresh_temp_dir("cache-lock");
    const auto made_elsewhere = test::fresh_temp_dir("cache-lock-other");
    const scene::Scene scene = one_texture_scene();
    // The entry as another process would leave it.
    const fs::path other_file =
        prepare_textures(scene, test::cache_test_options(made_elsewhere)).textures[0].cache_file;
    const fs::path entry = dir / other_file.filename();
    const Hash128 key{std::stoull(entry.stem().string().substr(0, 16), nullptr, 16),
                      std::stoull(entry.stem().string().substr(16), nullptr, 16)};

    // "Another process" (this test) holds the entry's lock while it makes the entry.
    const TextureCache cache(dir);
    std::optional<EntryLock> held(cache.lock_entry(key, std::chrono::milliseconds(0)));
    ASSERT_TRUE(held->held());
    std::promise<void> looked_up;
    PipelineOptions options = test::cache_test_options(dir);
    options.cache_lock_timeout = std::chrono::minutes(10);
    bool first_report = true;
    options.progress = [&](std::size_t, std::size_t) {
        if (std::exchange(first_report, false)) looked_up.set_value(); // lookup done: a miss
    };
    auto waiter = std::async(std::launch::async, [&] { return prepare_textures(scene, options); });
    looked_up.get_future().wait();
    fs::copy_file(other_file, entry); // the other process finishes ...
    held.reset();                     // ... and releases the lock
    const auto set = waiter.get();
    EXPECT_EQ(set.textures[0].state, CacheState::Hit) << set.textures[0].note;
    EXPECT_EQ(set.textures[0].encode_ms, 0.0); // nothing compressed twice
    fs::remove_all(dir);
    fs::remove_all(made_elsewhere);
}

// A regular file where the cache directory belongs: every lock failed and the warning
// blamed "another process"; now the file is named once and the textures are made.
TEST(CacheRobustness, CacheDirectoryThatIsAFileIsNamedAndBypassed) {
    const auto dir = test::fresh_temp_dir("cache-is-file");
    const fs::path not_a_dir = dir / "textures";
    write_bytes(not_a_dir, 10);
    const PreparedTextureSet set =
        prepare_textures(one_texture_scene(), test::cache_test_options(not_a_dir));
    ASSERT_EQ(set.textures.size(), 1u);
    EXPECT_FALSE(set.textures[0].failed);
    EXPECT_FALSE(set.textures[0].levels.empty());
    ASSERT_EQ(set.warnings.size(), 1u);
    EXPECT_EQ(set.warnings[0], "texture cache: " + not_a_dir.string() +
                                   ": is a regular file, not a directory; textures are made "
                                   "without the cache");
    fs::remove_all(dir);
}

// Lock files are empty and were never removed; one a minute old that nobody holds is.
TEST(CacheRobustness, StaleUnheldLockFilesAreRemoved) {
    const auto dir = test::fresh_temp_dir("cache-locks");
    const TextureCache cache(dir);
    const Hash128 held_key{1, 2};
    std::optional<EntryLock> held(cache.lock_entry(held_key, std::chrono::milliseconds(0)));
    ASSERT_TRUE(held->held());
    const fs::path held_lock = fs::path(cache.file_for(held_key).string() + ".lock");
    const fs::path stale = dir / "00000000000000000000000000000003.ktx2.lock";
    const fs::path fresh = dir / "00000000000000000000000000000004.ktx2.lock";
    write_bytes(stale, 0);
    write_bytes(fresh, 0);
    const auto two_minutes_ago = fs::file_time_type::clock::now() - std::chrono::minutes(2);
    fs::last_write_time(stale, two_minutes_ago);
    fs::last_write_time(held_lock, two_minutes_ago);
    cache.evict();
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(fresh));     // may be one a maker just opened
    EXPECT_TRUE(fs::exists(held_lock)); // its holder is making the entry
    held.reset();
    fs::remove_all(dir);
}
