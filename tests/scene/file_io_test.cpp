// Atomic writes: content replaced whole, no temp files left, ordinary permissions.
#include <sherpa/core/file_io.h>

#include <filesystem>
#include <sys/stat.h>

#include <gtest/gtest.h>

namespace {

TEST(FileIo, AtomicWriteReplacesTheFileWithUmaskPermissions) {
    const auto dir = std::filesystem::temp_directory_path() / "sherpa_file_io_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto path = dir / "out.bin";
    std::string error;
    const std::vector<std::uint8_t> a(1000, 1), b(10, 2);
    ASSERT_TRUE(sherpa::core::write_file_atomic(path, a, error)) << error;
    ASSERT_TRUE(sherpa::core::write_file_atomic(path, b, error)) << error;
    std::vector<std::uint8_t> back;
    ASSERT_TRUE(sherpa::core::read_file(path, back, error)) << error;
    EXPECT_EQ(back, b);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1)
        << "no temp files left";
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    const mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
    EXPECT_FALSE(sherpa::core::write_file_atomic(dir / "missing_dir" / "x", a, error));
    EXPECT_NE(error.find("missing_dir"), std::string::npos) << error;
    std::filesystem::remove_all(dir);
}

} // namespace
