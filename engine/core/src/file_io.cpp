#include <sherpa/core/file_io.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sherpa::core {

bool read_file(const std::filesystem::path& path, std::vector<std::uint8_t>& out,
               std::string& error) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        error = path.string() + ": cannot open: " + std::strerror(errno);
        return false;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = path.string() +
                (S_ISDIR(st.st_mode) ? ": is a directory, not a file" : ": not a regular file");
        ::close(fd);
        return false;
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    out.clear();
    out.reserve(static_cast<std::size_t>(st.st_size));
    std::uint8_t chunk[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, chunk, sizeof(chunk));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = path.string() + ": read error: " + std::strerror(errno);
            ::close(fd);
            return false;
        }
        if (n == 0) break;
        out.insert(out.end(), chunk, chunk + n);
    }
    ::close(fd);
    return true;
}

bool write_file_atomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                       std::string& error) {
    std::string tmpl = (path.parent_path() / (path.filename().string() + ".tmp." +
                                              std::to_string(::getpid()) + ".XXXXXX"))
                           .string();
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

long temp_file_writer_pid(std::string_view filename) {
    const std::size_t tmp = filename.rfind(".tmp.");
    if (tmp == std::string_view::npos) return 0;
    const std::string_view rest = filename.substr(tmp + 5); // "PID.XXXXXX"
    const std::size_t dot = rest.find('.');
    if (dot == 0 || dot == std::string_view::npos || dot > 9) return 0;
    long pid = 0;
    for (const char c : rest.substr(0, dot)) {
        if (c < '0' || c > '9') return 0;
        pid = pid * 10 + (c - '0');
    }
    return pid;
}

} // namespace sherpa::core
