#include "piglit_isolate.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

namespace glslrun::piglit {
namespace {

// Wire format: the payload's length as 8 decimal digits, then one outcome
// character ('p', 'f', 's') and the message. The length lets the parent stop
// reading without waiting for EOF.
constexpr size_t kHeader = 8;

std::string encode(const TestResult& r) {
    char c = r.outcome == Outcome::Pass ? 'p' : r.outcome == Outcome::Fail ? 'f' : 's';
    std::string payload = c + r.message.substr(0, 10'000'000);
    char header[kHeader + 1];
    std::snprintf(header, sizeof header, "%08zu", payload.size());
    return std::string(header, kHeader) + payload;
}

// The payload's length once the header has arrived.
std::optional<size_t> payload_size(const std::string& bytes) {
    if (bytes.size() < kHeader) return std::nullopt;
    size_t n = 0;
    for (size_t i = 0; i < kHeader; ++i) {
        if (bytes[i] < '0' || bytes[i] > '9') return std::nullopt;
        n = n * 10 + size_t(bytes[i] - '0');
    }
    return n;
}

std::optional<TestResult> decode(const std::string& bytes) {
    auto size = payload_size(bytes);
    if (!size || *size == 0 || bytes.size() != kHeader + *size) return std::nullopt;
    const std::string payload = bytes.substr(kHeader);
    if (payload.empty()) return std::nullopt;
    TestResult r;
    switch (payload[0]) {
    case 'p': r.outcome = Outcome::Pass; break;
    case 'f': r.outcome = Outcome::Fail; break;
    case 's': r.outcome = Outcome::Skip; break;
    default: return std::nullopt;
    }
    r.message = payload.substr(1);
    return r;
}

[[noreturn]] void child_main(int fd, const std::function<TestResult()>& fn) {
    // A crash must kill the child so the parent can name the signal, whatever
    // handlers the parent installed (test frameworks install some).
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, SIG_DFL);
    TestResult r;
    try {
        r = fn();
    } catch (const std::exception& e) {
        r = {Outcome::Fail, std::string("internal error: ") + e.what()};
    } catch (...) {
        r = {Outcome::Fail, "internal error: unknown exception"};
    }
    std::string bytes = encode(r);
    size_t off = 0;
    while (off < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + off, bytes.size() - off);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        off += size_t(n);
    }
    ::close(fd);
    ::_exit(0);  // no atexit handlers or static destructors of the parent's state
}

// Reads the child's pipe until the whole result or EOF arrived; false on timeout.
bool read_until_eof(int fd, std::string& out, std::chrono::steady_clock::time_point deadline) {
    char buf[4096];
    while (true) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        pollfd p{fd, POLLIN, 0};
        int ready = ::poll(&p, 1, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return true;
        out.append(buf, size_t(n));
        if (auto size = payload_size(out); size && out.size() >= kHeader + *size) return true;
    }
}

std::string describe_status(int status) {
    if (WIFSIGNALED(status)) {
        int sig = WTERMSIG(status);
        const char* name = ::sigabbrev_np(sig);
        return "crashed: signal " + std::to_string(sig) + (name ? std::string(" (SIG") + name + ")" : "");
    }
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result";
    return "ended without a result";
}

// fork() and pipe2() fail with EAGAIN at a process or descriptor limit that
// other children are about to free, so they are retried for a while.
template <typename Call>
int retry_while_busy(Call call) {
    int result = -1;
    for (int attempt = 0; attempt < 50; ++attempt) {
        result = call();
        if (result >= 0 || (errno != EAGAIN && errno != ENOMEM && errno != EMFILE && errno != ENFILE)) break;
        ::usleep(20'000);
    }
    return result;
}

TestResult not_isolated(const char* what) {
    return {Outcome::Fail, std::string("not run: ") + what + " failed: " + std::strerror(errno)};
}

}  // namespace

TestResult run_isolated(const std::function<TestResult()>& fn, double timeout_s) {
    int fds[2];
    if (retry_while_busy([&] { return ::pipe2(fds, O_CLOEXEC); }) != 0) return not_isolated("pipe2");
    if (fds[1] < 3) {  // stdio was closed: move the write end above it, where the child keeps it
        int moved = ::fcntl(fds[1], F_DUPFD_CLOEXEC, 3);
        ::close(fds[1]);
        if (moved < 0) {
            ::close(fds[0]);
            return not_isolated("fcntl");
        }
        fds[1] = moved;
    }
    pid_t pid = retry_while_busy([] { return int(::fork()); });
    if (pid < 0) {
        int saved = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        errno = saved;
        return not_isolated("fork");
    }
    if (pid == 0) {
        // Drop every other descriptor, including the pipes of tests that other
        // threads are running right now.
        if (fds[1] > 3) ::close_range(3, unsigned(fds[1]) - 1, 0);
        ::close_range(unsigned(fds[1]) + 1, ~0u, 0);
        child_main(fds[1], fn);
    }
    ::close(fds[1]);
    auto deadline = std::chrono::steady_clock::now() +
                    std::chrono::milliseconds(static_cast<long long>(timeout_s * 1000));
    std::string bytes;
    bool finished = read_until_eof(fds[0], bytes, deadline);
    ::close(fds[0]);
    if (!finished) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (!finished)
        return {Outcome::Fail, "timed out after " + std::to_string(static_cast<long long>(timeout_s)) + " s"};
    if (auto r = decode(bytes)) return *r;
    return {Outcome::Fail, describe_status(status)};
}

}  // namespace glslrun::piglit
