#include <sherpa/core/file_io.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sherpa {

bool read_file(const std::filesystem::path& path, std::vector<std::uint8_t>& out,
               std::string& error) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        error = path.string() + ": cannot open: " + std::strerror(errno);
        return false;
    }
    out.clear();
    std::uint8_t chunk[1 << 16];
    std::size_t n = 0;
    while ((n = std::fread(chunk, 1, sizeof(chunk), f)) > 0)
        out.insert(out.end(), chunk, chunk + n);
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) {
        error = path.string() + ": read error";
        return false;
    }
    return true;
}

bool write_file_atomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                       std::string& error) {
    std::string tmpl = (path.parent_path() / (path.filename().string() + ".tmp.XXXXXX")).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) {
        error = path.string() + ": cannot create temp file: " + std::strerror(errno);
        return false;
    }
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t w = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            error = path.string() + ": write failed: " + std::strerror(errno);
            ::close(fd);
            ::unlink(tmpl.c_str());
            return false;
        }
        written += static_cast<std::size_t>(w);
    }
    // mkstemp creates the file 0600; give it the mode a plain create would have
    // (0666 less the umask), so atomic writes do not make private files.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd, 0666 & ~mask) != 0 || ::fsync(fd) != 0 || ::close(fd) != 0) {
        error = path.string() + ": fsync/close failed: " + std::strerror(errno);
        ::unlink(tmpl.c_str());
        return false;
    }
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
        error = path.string() + ": rename failed: " + std::strerror(errno);
        ::unlink(tmpl.c_str());
        return false;
    }
    return true;
}

} // namespace sherpa
