#include "cache_files.h"

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/texture_cache.h>

namespace sherpa::tex {

namespace fs = std::filesystem;

bool abandoned_temp_file(std::string_view filename, fs::file_time_type::duration age) {
    if (age > std::chrono::hours(1)) return true;
    const long pid = core::temp_file_writer_pid(filename);
    if (pid <= 0 || age < std::chrono::minutes(1)) return false;
    // kill(pid, 0) probes without signalling; ESRCH: no such process. EPERM means
    // it exists (another user's), so the file stays.
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

fs::path lock_file_for(const fs::path& entry) {
    return fs::path(entry.string() + ".lock");
}

void remove_unused_lock(const fs::path& entry) {
    remove_lock_if_unused(lock_file_for(entry));
}

void remove_lock_if_unused(const fs::path& lock) {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) return;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) ::unlink(lock.c_str());
    ::close(fd); // releases the lock
}

EntryLock& EntryLock::operator=(EntryLock&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

EntryLock::~EntryLock() {
    if (fd_ >= 0) ::close(fd_); // closing the descriptor releases the flock
}

EntryLock TextureCache::lock_entry(const Hash128& key, std::chrono::milliseconds timeout) const {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    const fs::path lock = lock_file_for(file_for(key));
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0) return {};
    // Polled rather than a blocking flock: a blocking call cannot time out.
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (auto wait = std::chrono::milliseconds(1);;
         wait = std::min(wait * 2, std::chrono::milliseconds(50))) {
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return EntryLock(fd);
        if (errno != EWOULDBLOCK && errno != EINTR) break;
        if (std::chrono::steady_clock::now() >= deadline) break;
        std::this_thread::sleep_for(wait);
    }
    ::close(fd);
    return {};
}

} // namespace sherpa::tex
