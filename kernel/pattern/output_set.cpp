#include "kernel/pattern/output_set.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace {

namespace fs = std::filesystem;

// ---- temporaries, visible to a signal handler -------------------------------------------
// A list of fixed buffers that only grows (nodes are reused, never freed), published by one
// atomic store: the handler walks it without locks or allocation.
struct PendingTemp {
  char path[PATH_MAX];
  volatile std::sig_atomic_t active = 0;  // the file at `path` may exist and is ours
  bool claimed = false;                   // owned by an OutputSet (main thread only)
  PendingTemp* next = nullptr;
};
std::atomic<PendingTemp*> g_pending{nullptr};

PendingTemp* claim_node() {
  for (PendingTemp* p = g_pending.load(); p; p = p->next)
    if (!p->claimed) {
      p->claimed = true;
      return p;
    }
  auto* n = new PendingTemp;
  n->claimed = true;
  n->next = g_pending.load();
  g_pending.store(n);
  return n;
}

void release_node(PendingTemp* n) {
  n->active = 0;
  n->claimed = false;
}

bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

mode_t process_umask() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(0);
    ::umask(m);
    return m;
  }();
  return mask;
}

std::string kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

std::string errno_text() { return std::strerror(errno); }

// A path as the command will use it: absolute, symlinks followed (also a dangling one, whose
// target is then created), "." and ".." gone; and the file it names, if it exists.
struct Resolved {
  fs::path path;
  bool is_stdout = false;
  bool exists = false;
  struct stat st {};
};

Resolved resolve(const std::string& label, const std::string& given) {
  Resolved r;
  if (given == "-") {
    r.is_stdout = true;
    return r;
  }
  if (given.empty()) throw InputError(label, "empty path");
  std::error_code ec;
  if (::stat(given.c_str(), &r.st) == 0) {
    r.exists = true;
    // A device or FIFO is opened by the name given (/dev/stdout is a link to "pipe:[N]").
    if (S_ISREG(r.st.st_mode) || S_ISDIR(r.st.st_mode)) r.path = fs::canonical(given, ec);
    if (r.path.empty() || ec) r.path = fs::absolute(given, ec).lexically_normal();
    return r;
  }
  if (errno == ELOOP) throw InputError(label, given + ": too many levels of symbolic links");
  fs::path p = fs::absolute(given, ec);
  for (int hops = 0;; ++hops) {
    struct stat lst {};
    if (::lstat(p.c_str(), &lst) != 0 || !S_ISLNK(lst.st_mode)) break;
    if (hops == 40) throw InputError(label, given + ": too many levels of symbolic links");
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  r.path = fs::weakly_canonical(p, ec);
  if (ec || r.path.empty()) r.path = p.lexically_normal();
  return r;
}

bool same_file(const Resolved& a, const Resolved& b) {
  if (a.is_stdout || b.is_stdout) return a.is_stdout && b.is_stdout;
  if (a.exists && b.exists) return a.st.st_dev == b.st.st_dev && a.st.st_ino == b.st.st_ino;
  return a.path == b.path;
}

std::string named(const std::string& label, const std::string& given) {
  return label.empty() ? given : label + " (" + given + ")";
}

}  // namespace

struct OutputSet::Input {
  std::string label, given;
  Resolved r;
};

struct OutputSet::Output {
  enum class Kind { Replace, InPlace, Stdout };
  std::string label, given;
  Resolved r;
  Kind kind = Kind::Replace;
  mode_t mode = 0666;
  bool staged = false;
  std::string text;               // InPlace and Stdout: written at commit
  PendingTemp* temp = nullptr;    // Replace: the staged temporary
};

OutputSet::OutputSet() = default;

OutputSet::~OutputSet() {
  if (!committed_) rollback();
  for (auto& o : outputs_)
    if (o->temp) release_node(o->temp);
}

void OutputSet::rollback() noexcept {
  for (auto& o : outputs_)
    if (o->temp && o->temp->active) {
      ::unlink(o->temp->path);
      release_node(o->temp);
      o->temp = nullptr;
    }
  for (auto it = created_directories_.rbegin(); it != created_directories_.rend(); ++it) ::rmdir(it->c_str());
  created_directories_.clear();
}

void OutputSet::add_input(const std::string& label, const std::string& path) {
  Input in{label, path, resolve(label, path)};
  for (const auto& o : outputs_)
    if (same_file(in.r, o->r))
      throw InputError(o->label, o->given + " is the same file as the input " + named(label, path) +
                                     ": an output must not overwrite an input");
  inputs_.push_back(std::move(in));
}

void OutputSet::add_output_directory(const std::string& label, const std::string& path) {
  const Resolved r = resolve(label, path);
  if (r.is_stdout) throw InputError(label, "must be a directory, not standard output");
  for (const auto& in : inputs_)
    if (same_file(r, in.r))
      throw InputError(label, path + " is the same directory as the input " + named(in.label, in.given) +
                                  ": the outputs would be read as inputs by the next run, and could overwrite them");
  if (r.exists) {
    if (!S_ISDIR(r.st.st_mode)) throw InputError(label, path + ": exists and is not a directory");
    return;
  }
  // Create the missing levels one by one, recording each for rollback.
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = r.path; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST)
      throw InputError(label, path + ": cannot create directory " + it->string() + ": " + errno_text());
    created_directories_.push_back(it->string());
  }
}

void OutputSet::add_output(const std::string& label, const std::string& path) {
  auto o = std::make_unique<Output>();
  o->label = label;
  o->given = path;
  o->r = resolve(label, path);
  const std::string where = path + ": ";
  if (o->r.is_stdout) {
    o->kind = Output::Kind::Stdout;
  } else if (o->r.exists && (S_ISCHR(o->r.st.st_mode) || S_ISFIFO(o->r.st.st_mode))) {
    o->kind = Output::Kind::InPlace;
    if (::access(path.c_str(), W_OK) != 0) throw InputError(label, where + "cannot write: " + errno_text());
  } else if (o->r.exists && !S_ISREG(o->r.st.st_mode)) {
    throw InputError(label, where + "is " + kind_of(o->r.st.st_mode) + "; an output must be a file, a character device, a FIFO or -");
  } else {
    const fs::path dir = o->r.path.parent_path();
    struct stat dst {};
    if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
      throw InputError(label, where + "directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK | X_OK) != 0) throw InputError(label, where + "cannot write in directory " + dir.string() + ": " + errno_text());
    if (o->r.exists) {
      if (::access(o->r.path.c_str(), W_OK) != 0) throw InputError(label, where + "exists and is not writable: " + errno_text());
      o->mode = o->r.st.st_mode & 0777;  // a replaced file keeps its permissions
    } else {
      long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
      if (name_max <= 0) name_max = NAME_MAX;
      if (static_cast<long>(o->r.path.filename().string().size()) > name_max)
        throw InputError(label, where + "file name longer than " + std::to_string(name_max) + " bytes");
      o->mode = 0666 & ~process_umask();
    }
  }
  for (const auto& in : inputs_)
    if (same_file(o->r, in.r))
      throw InputError(label, path + " is the same file as the input " + named(in.label, in.given) +
                                  ": an output must not overwrite an input");
  for (const auto& other : outputs_) {
    const bool both_devices = o->r.exists && other->r.exists && S_ISCHR(o->r.st.st_mode) && S_ISCHR(other->r.st.st_mode);
    if (same_file(o->r, other->r) && !both_devices)
      throw InputError(label, path + " is the same file as " + named(other->label, other->given) + ": two outputs on one path");
  }
  outputs_.push_back(std::move(o));
}

OutputSet::Output& OutputSet::find(const std::string& path) {
  for (auto& o : outputs_)
    if (o->given == path) return *o;
  throw std::logic_error("OutputSet: output " + path + " was not declared");
}

bool OutputSet::writes_stdout() const {
  for (const auto& o : outputs_)
    if (o->kind == Output::Kind::Stdout) return true;
  return false;
}

bool OutputSet::writes_in_place(const std::string& path) const {
  for (const auto& o : outputs_)
    if (o->given == path) return o->kind != Output::Kind::Replace;
  return false;
}

void OutputSet::stage(const std::string& path, const std::string& text) {
  if (committed_) throw std::logic_error("OutputSet: stage after commit");
  Output& o = find(path);
  if (o.kind != Output::Kind::Replace) {  // a stream takes every text staged for it, in order
    o.text += text;
    o.staged = true;
    return;
  }
  if (o.staged) throw std::logic_error("OutputSet: " + path + " staged twice");
  const fs::path dir = o.r.path.parent_path();
  const std::string name = o.r.path.filename().string();
  long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  if (name_max <= 0) name_max = NAME_MAX;
  const std::string suffix = ".tmp.XXXXXX";  // mkostemp's template
  const std::size_t keep = std::min<std::size_t>(name.size(), static_cast<std::size_t>(name_max) - 1 - suffix.size());
  std::string tmp_name = ".";
  tmp_name += name.substr(0, keep);
  tmp_name += suffix;
  const std::string tmp = (dir / tmp_name).string();
  if (tmp.size() >= sizeof(PendingTemp::path)) throw InputError(o.label, path + ": output path is too long");
  PendingTemp* node = claim_node();
  std::memcpy(node->path, tmp.c_str(), tmp.size() + 1);
  node->active = 1;  // before the file exists, so a signal never misses it
  const int fd = ::mkostemp(node->path, O_CLOEXEC);  // exclusive: never an existing file or link
  if (fd < 0) {
    const std::string err = errno_text();
    release_node(node);
    throw InputError(o.label, path + ": cannot create a temporary file in " + dir.string() + ": " + err);
  }
  o.temp = node;
  const bool written = write_all(fd, text);
  const std::string err = errno_text();
  const bool moded = ::fchmod(fd, o.mode) == 0;
  const bool closed = ::close(fd) == 0;
  if (!written || !moded || !closed) throw InputError(o.label, path + ": write failed: " + (written ? errno_text() : err));
  o.staged = true;
}

void OutputSet::commit() {
  if (committed_) throw std::logic_error("OutputSet: committed twice");
  // Streams first: a failure there (a FIFO without a reader, /dev/full) leaves every
  // replaced file untouched.
  for (auto& o : outputs_) {
    if (!o->staged || o->kind == Output::Kind::Replace) continue;
    struct sigaction ignore {}, old {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &old);  // a reader that goes away is an error, not a death
    std::string failure;
    if (o->kind == Output::Kind::Stdout) {
      std::cout.flush();
      if (!write_all(STDOUT_FILENO, o->text)) failure = "cannot write to standard output: " + errno_text();
    } else {
      int fd = -1;
      if (S_ISFIFO(o->r.st.st_mode)) {
        // Non-blocking open fails (ENXIO) until a reader opens the FIFO: wait for one, bounded.
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(kFifoWaitSeconds);
        while ((fd = ::open(o->given.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)) < 0 && errno == ENXIO &&
               std::chrono::steady_clock::now() < give_up)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        else if (errno == ENXIO) failure = "FIFO has no reader (waited " + std::to_string(kFifoWaitSeconds) + " s)";
      } else {
        fd = ::open(o->given.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      }
      if (fd < 0 && failure.empty()) failure = "cannot open: " + errno_text();
      if (fd >= 0) {
        if (!write_all(fd, o->text)) failure = "write failed: " + errno_text();
        ::close(fd);
      }
    }
    ::sigaction(SIGPIPE, &old, nullptr);
    if (!failure.empty()) throw InputError(o->label, o->given + ": " + failure);
  }
  for (auto& o : outputs_) {
    if (!o->staged || o->kind != Output::Kind::Replace) continue;
    if (::rename(o->temp->path, o->r.path.c_str()) != 0)
      throw InputError(o->label, o->given + ": cannot rename the temporary file into place: " + errno_text());
    release_node(o->temp);
    o->temp = nullptr;
  }
  committed_ = true;
  created_directories_.clear();
}

void remove_staged_temporaries() {
  for (PendingTemp* p = g_pending.load(); p; p = p->next)
    if (p->active) ::unlink(p->path);
}

}  // namespace rigidfold
