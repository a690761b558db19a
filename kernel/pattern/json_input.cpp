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

// SAX handler that builds the document itself, with a depth count on every array and object
// start and a check for keys given twice. Not nlohmann's json_sax_dom_parser, and not a
// parser callback: both insert each key of an ordered_json object by a linear search of the
// keys before it (ordered_map::operator[]), quadratic in the key count (200,000 keys took 97 s),
// and the callback parser also rescans the parent array after every object in it. Keys are
// unique here (checked in a hash set), so a key is appended without a search: reading is
// linear in the input.
template <class Json>
class DepthLimitedDom {
 public:
  using number_integer_t = typename Json::number_integer_t;
  using number_unsigned_t = typename Json::number_unsigned_t;
  using number_float_t = typename Json::number_float_t;
  using string_t = typename Json::string_t;
  using binary_t = typename Json::binary_t;

  explicit DepthLimitedDom(Json& root) : root_(root) {}
  bool null() { return put(Json(nullptr)); }
  bool boolean(bool v) { return put(Json(v)); }
  bool number_integer(number_integer_t v) { return put(Json(v)); }
  bool number_unsigned(number_unsigned_t v) { return put(Json(v)); }
  bool number_float(number_float_t v, const string_t&) { return put(Json(v)); }
  bool string(string_t& v) { return put(Json(std::move(v))); }
  bool binary(binary_t& v) { return put(Json::binary(std::move(v))); }
  bool key(string_t& v) {
    // JSON allows a key twice in one object, but which value is meant is then ambiguous
    // (nlohmann keeps the last): refused, like a syntax error.
    Level& top = levels_.back();
    if (!top.keys.insert(v).second) throw DuplicateKey{path_to(v), v};
    top.key = v;
    slot_ = &append_member(*open_.back(), v);
    return true;
  }
  bool start_object(std::size_t) {
    Json* object = place(Json(nlohmann::json::value_t::object));
    enter(false);
    open_.push_back(object);
    return true;
  }
  bool end_object() {
    leave();
    return true;
  }
  bool start_array(std::size_t) {
    Json* array = place(Json(nlohmann::json::value_t::array));
    enter(true);
    open_.push_back(array);
    return true;
  }
  bool end_array() {
    leave();
    return true;
  }
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& ex) {
    throw ex;  // parse_error, or out_of_range 406 (a number that does not fit a double)
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
  // A new member of `object`, null until its value is placed. The key is known to be new.
  static Json& append_member(Json& object, const std::string& key) {
    auto& members = object.template get_ref<typename Json::object_t&>();
    if constexpr (requires { typename Json::object_t::Container; }) {
      auto& list = static_cast<typename Json::object_t::Container&>(members);  // ordered_map: a vector of pairs
      list.emplace_back(key, Json());
      return list.back().second;
    } else {
      return members.emplace(key, Json()).first->second;
    }
  }
  // Puts a value where the parser is: the root, the next element of the open array, or the
  // member whose key was just read. Returns where it now lives (stable while it is open:
  // nothing is added to its parent until it is closed).
  Json* place(Json&& value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Level& top = levels_.back();
    if (top.array) {
      ++top.count;
      auto& elements = open_.back()->template get_ref<typename Json::array_t&>();
      elements.push_back(std::move(value));
      return &elements.back();
    }
    *slot_ = std::move(value);
    return slot_;
  }
  bool put(Json&& value) {
    place(std::move(value));
    return true;
  }
  void enter(bool array) {
    if (static_cast<int>(levels_.size()) + 1 > kMaxJsonDepth) throw TooDeep{};
    levels_.push_back(Level{array, 0, {}, {}});
  }
  void leave() {
    levels_.pop_back();
    open_.pop_back();
  }
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
  Json& root_;
  std::vector<Json*> open_;  // the open arrays and objects, outermost first
  std::vector<Level> levels_;
  Json* slot_ = nullptr;     // the member whose key was read last
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
