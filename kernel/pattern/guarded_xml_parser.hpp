#pragma once
// GuardedXmlParser: Expat with the refusals every XML reader of the project needs (the SVG and
// ORIPA .opx readers derive from it), so that they are written once.
//   - A document type with an internal subset, any entity declaration and any entity reference
//     other than XML's five are refused ("billion laughs"); parameter entities are never parsed.
//   - Handlers run inside Expat (C), which no exception may cross: the first exception a
//     handler throws is kept, the parser stopped, and parse_xml() rethrows it.
//   - A malformed document: InputError("SOURCE: line L, column C", "XML: <Expat's message>").
// The reader's limits (elements, depth) are the reader's own, in its handlers.
#include <exception>
#include <string>

namespace rigidfold {

class GuardedXmlParser {
 public:
  explicit GuardedXmlParser(std::string source) : source_(std::move(source)) {}
  virtual ~GuardedXmlParser() = default;
  GuardedXmlParser(const GuardedXmlParser&) = delete;
  GuardedXmlParser& operator=(const GuardedXmlParser&) = delete;

 protected:
  // Parses the whole text, calling the handlers below. namespace_separator != 0: element
  // names arrive as "URI<separator>local" (Expat's namespace processing).
  void parse_xml(const std::string& text, char namespace_separator = '\0');
  virtual void start_element(const char* name, const char** attributes) = 0;  // attributes: name, value, ..., null
  virtual void end_element() = 0;
  virtual void character_data(const char* /*text*/, int /*length*/) {}

  long current_line() const;  // of the event being handled (0 outside parse_xml)
  std::string here() const { return source_ + ": line " + std::to_string(current_line()); }

  const std::string source_;  // the file, as messages name it

 private:
  struct Callbacks;
  void* parser_ = nullptr;  // the XML_Parser while parse_xml runs
  std::exception_ptr error_;
};

}  // namespace rigidfold
