#include "gltf_fs.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sherpa::scene::detail {
namespace {

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

// Closes the descriptor on every path out of read_regular_file.
struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

bool read_regular_file(const std::string& path, std::vector<std::uint8_t>& out,
                       std::string& error) {
    if (path.find('\0') != std::string::npos) {
        error = "the path contains a NUL byte";
        return false;
    }
    // O_NONBLOCK: opening a FIFO without a writer must not hang; fstat on the open
    // descriptor (not stat on the name) so the file checked is the file read.
    const Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (f.fd < 0) {
        error = std::string("cannot open: ") + std::strerror(errno);
        return false;
    }
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) {
        error = std::string("cannot stat: ") + std::strerror(errno);
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        error = kind_of(st.st_mode);
        return false;
    }
    out.clear();
    out.reserve(static_cast<std::size_t>(st.st_size));
    std::uint8_t chunk[1 << 16];
    for (;;) {
        const ssize_t n = ::read(f.fd, chunk, sizeof(chunk));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::string("read error: ") + std::strerror(errno);
            return false;
        }
        if (n == 0) break;
        out.insert(out.end(), chunk, chunk + n);
    }
    return true;
}

tinygltf::FsCallbacks safe_fs_callbacks() {
    tinygltf::FsCallbacks fs{};
    // "Exists" for anything stat can see, so that ReadWholeFile gets to say what it is.
    fs.FileExists = [](const std::string& path, void*) {
        struct stat st {};
        return path.find('\0') == std::string::npos && ::stat(path.c_str(), &st) == 0;
    };
    fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
    fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err,
                          const std::string& path, void*) {
        std::string error;
        if (read_regular_file(path, *out, error)) return true;
        if (err) *err += error;
        return false;
    };
    fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&,
                           void*) {
        if (err) *err += "the importer never writes files";
        return false;
    };
    fs.user_data = nullptr;
    return fs;
}

} // namespace sherpa::scene::detail
