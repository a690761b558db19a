#include "kernel/pattern/json_input.hpp"

#include <algorithm>
#include <unordered_set>
#include <vector>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"

namespace rigidfold {
namespace {

// Closes a file descriptor on every path out of read_input_file.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string kind_of(const struct stat& st) {
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

std::string mib(std::uintmax_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Thrown when the nesting passes the limit; carries nothing, the caller words the message.
struct TooDeep {};
// Thrown at the second occurrence of a key in one object; path names it ("a[2].b").
struct DuplicateKey {
  std::string path, key;
};

// SAX handler: nlohmann's own DOM builder, with a depth count on every array and object
// start. (Not a parser callback: nlohmann 3.11's callback parser rescans the parent array
// after every object in it, quadratic in the array's length - 1e5 objects took 4 s.)
template <class Json>
class DepthLimitedDom {
 public:
  using number_integer_t = typename Json::number_integer_t;
  using number_unsigned_t = typename Json::number_unsigned_t;
  using number_float_t = typename Json::number_float_t;
  using string_t = typename Json::string_t;
  using binary_t = typename Json::binary_t;

  explicit DepthLimitedDom(Json& root) : dom_(root, true) {}
  bool null() { return value(), dom_.null(); }
  bool boolean(bool v) { return value(), dom_.boolean(v); }
  bool number_integer(number_integer_t v) { return value(), dom_.number_integer(v); }
  bool number_unsigned(number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& text) { return value(), dom_.number_float(v, text); }
  bool string(string_t& v) { return value(), dom_.string(v); }
  bool binary(binary_t& v) { return value(), dom_.binary(v); }
  bool key(string_t& v) {
    // JSON allows a key twice in one object, but which value is meant is then ambiguous
    // (nlohmann keeps the last): refused, like a syntax error.
    Level& top = levels_.back();
    if (!top.keys.insert(v).second) throw DuplicateKey{path_to(v), v};
    top.key = v;
    return dom_.key(v);
  }
  bool start_object(std::size_t n) {
    value();
    enter(false);
    return dom_.start_object(n);
  }
  bool end_object() {
    leave();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    value();
    enter(true);
    return dom_.start_array(n);
  }
  bool end_array() {
    leave();
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    return dom_.parse_error(position, token, ex);  // throws ex (parse_error, or out_of_range 406)
  }

 private:
  // One open array or object: the index of its current element, or its current key and the
  // keys seen so far.
  struct Level {
    bool array = false;
    std::size_t count = 0;
    std::string key;
    std::unordered_set<std::string> keys;
  };
  void value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().count;
  }
  void enter(bool array) {
    if (static_cast<int>(levels_.size()) + 1 > kMaxJsonDepth) throw TooDeep{};
    levels_.push_back(Level{array, 0, {}, {}});
  }
  void leave() { levels_.pop_back(); }
  std::string path_to(const std::string& key) const {
    std::string path;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      const Level& l = levels_[i];
      if (l.array) {
        path += "[" + std::to_string(l.count - 1) + "]";
      } else {
        if (!path.empty()) path += ".";
        path += i + 1 == levels_.size() ? key : l.key;
      }
    }
    return path;
  }
  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::vector<Level> levels_;
};

template <class Json>
Json parse_limited(const std::string& text, const std::string& source) {
  Json doc;
  DepthLimitedDom<Json> sax(doc);
  try {
    Json::sax_parse(text, &sax);
  } catch (const DuplicateKey& d) {
    throw InputError(source + ": " + d.path, "duplicate key \"" + d.key + "\" (JSON leaves which value is meant ambiguous)");
  } catch (const TooDeep&) {
    throw InputError(source, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                                 " arrays/objects (the limit for every input file)");
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(source, "not valid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  } catch (const nlohmann::json::exception& e) {  // out_of_range 406: a number that does not fit a double
    throw InputError(source, std::string("not valid JSON: ") + e.what());
  }
  return doc;
}

}  // namespace

std::string read_input_file(const std::string& path) {
  FileDescriptor f;
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting.
  f.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (f.fd < 0) throw InputError(path, std::string("cannot open file: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw InputError(path, std::string("cannot stat file: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(path, "is " + kind_of(st) + "; input must be a regular file");
  if (static_cast<std::uintmax_t>(st.st_size) > kMaxInputFileBytes)
    throw InputError(path, "file is " + std::to_string(st.st_size) + " bytes, over the input limit of " +
                               mib(kMaxInputFileBytes));
  std::string text;
  text.resize(static_cast<std::size_t>(st.st_size));
  std::size_t filled = 0;
  char chunk[65536];
  for (;;) {
    // Read into the sized buffer, then past it in case the file grew since fstat.
    char* dst = filled < text.size() ? text.data() + filled : chunk;
    const std::size_t room = filled < text.size() ? text.size() - filled : sizeof chunk;
    const ssize_t n = ::read(f.fd, dst, room);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path, std::string("read error: ") + std::strerror(errno));
    }
    if (n == 0) break;
    if (dst == chunk) {
      if (text.size() + static_cast<std::size_t>(n) > kMaxInputFileBytes)
        throw InputError(path, "file grew past the input limit of " + mib(kMaxInputFileBytes) + " while it was read");
      text.append(chunk, static_cast<std::size_t>(n));
    }
    filled += static_cast<std::size_t>(n);
  }
  text.resize(std::min(filled, text.size()));
  return text;
}

nlohmann::json parse_json_input(const std::string& text, const std::string& source) {
  return parse_limited<nlohmann::json>(text, source);
}

nlohmann::ordered_json parse_ordered_json_input(const std::string& text, const std::string& source) {
  return parse_limited<nlohmann::ordered_json>(text, source);
}

}  // namespace rigidfold
