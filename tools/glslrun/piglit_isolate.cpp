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
#include <variant>
#include <vector>

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

using Clock = std::chrono::steady_clock;

// A test whose child is running: its pipe's read end and what arrived so far.
struct Child {
    size_t index = 0;
    pid_t pid = -1;
    int fd = -1;
    std::string bytes;
    Clock::time_point start, deadline;
};

// Forks the child for test `index`; a result instead when pipe2 or fork fails.
std::variant<Child, TestResult> start_child(size_t index, const IsolatedTest& fn, double timeout_s) {
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
        // Drop every other descriptor, including the pipes of the other running children.
        if (fds[1] > 3) ::close_range(3, unsigned(fds[1]) - 1, 0);
        ::close_range(unsigned(fds[1]) + 1, ~0u, 0);
        child_main(fds[1], [&] { return fn(index); });
    }
    ::close(fds[1]);
    Child child{index, pid, fds[0], {}, Clock::now(), {}};
    child.deadline = child.start + std::chrono::milliseconds(static_cast<long long>(timeout_s * 1000));
    return child;
}

// Reads what the child's pipe holds now; true once the whole result or EOF arrived.
bool read_available(Child& child) {
    char buf[65536];
    ssize_t n = ::read(child.fd, buf, sizeof buf);
    if (n < 0) return errno != EINTR && errno != EAGAIN;
    if (n == 0) return true;
    child.bytes.append(buf, size_t(n));
    auto size = payload_size(child.bytes);
    return size && child.bytes.size() >= kHeader + *size;
}

// Ends a child (killed first when it ran out of time) and makes its result.
TestResult finish_child(Child& child, bool timed_out, double timeout_s) {
    ::close(child.fd);
    if (timed_out) ::kill(child.pid, SIGKILL);
    int status = 0;
    while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {}
    TestResult r;
    if (timed_out)
        r = {Outcome::Fail, "timed out after " + std::to_string(static_cast<long long>(timeout_s)) + " s"};
    else if (auto decoded = decode(child.bytes))
        r = *decoded;
    else
        r = {Outcome::Fail, describe_status(status)};
    r.seconds = std::chrono::duration<double>(Clock::now() - child.start).count();
    return r;
}

// Waits until some child's pipe is readable or the earliest deadline passes
// (at most a second), then advances every child; finished ones leave `running`.
void advance_children(std::vector<Child>& running, double timeout_s,
                      const std::function<void(size_t, TestResult)>& finished) {
    std::vector<pollfd> polls;
    auto earliest = running.front().deadline;
    for (const Child& c : running) {
        polls.push_back({c.fd, POLLIN, 0});
        earliest = std::min(earliest, c.deadline);
    }
    auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(earliest - Clock::now()).count();
    int ready = ::poll(polls.data(), polls.size(), int(std::clamp<long long>(wait + 1, 0, 1000)));
    if (ready < 0 && errno != EINTR) ready = 0;
    auto now = Clock::now();
    std::vector<Child> still_running;
    for (size_t i = 0; i < running.size(); ++i) {
        Child& c = running[i];
        bool done = ready > 0 && polls[i].revents != 0 && read_available(c);
        if (done || now >= c.deadline)
            finished(c.index, finish_child(c, !done, timeout_s));
        else
            still_running.push_back(std::move(c));
    }
    running = std::move(still_running);
}

}  // namespace

std::vector<TestResult> run_isolated_tests(size_t count, int jobs, const IsolatedTest& fn, double timeout_s,
                                           const Report& report) {
    std::vector<TestResult> results(count);
    std::vector<char> done(count, 0);
    size_t next = 0, reported = 0;
    auto finished = [&](size_t index, TestResult r) {
        results[index] = std::move(r);
        done[index] = 1;
    };
    std::vector<Child> running;
    jobs = std::clamp(jobs, 1, 256);
    while (reported < count) {
        while (running.size() < size_t(jobs) && next < count) {
            auto started = start_child(next, fn, timeout_s);
            if (auto* child = std::get_if<Child>(&started)) running.push_back(std::move(*child));
            else finished(next, std::get<TestResult>(std::move(started)));
            ++next;
        }
        for (; reported < count && done[reported]; ++reported)
            if (report) report(reported, results[reported]);
        if (!running.empty()) advance_children(running, timeout_s, finished);
    }
    return results;
}

TestResult run_isolated(const std::function<TestResult()>& fn, double timeout_s) {
    return run_isolated_tests(1, 1, [&](size_t) { return fn(); }, timeout_s, nullptr)[0];
}

}  // namespace glslrun::piglit
