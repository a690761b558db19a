#include "kernel/pattern/guarded_xml_parser.hpp"

#include <expat.h>

#include <new>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold {

struct GuardedXmlParser::Callbacks {
  template <class F>
  static void guarded(void* self_ptr, F&& f) {
    auto* self = static_cast<GuardedXmlParser*>(self_ptr);
    if (self->error_) return;
    try {
      f(*self);
    } catch (...) {
      self->error_ = std::current_exception();
      XML_StopParser(static_cast<XML_Parser>(self->parser_), XML_FALSE);
    }
  }
  static void XMLCALL on_start(void* p, const XML_Char* name, const XML_Char** atts) {
    guarded(p, [&](GuardedXmlParser& s) { s.start_element(name, atts); });
  }
  static void XMLCALL on_end(void* p, const XML_Char*) {
    guarded(p, [&](GuardedXmlParser& s) { s.end_element(); });
  }
  static void XMLCALL on_text(void* p, const XML_Char* text, int len) {
    guarded(p, [&](GuardedXmlParser& s) { s.character_data(text, len); });
  }
  static void XMLCALL on_doctype(void* p, const XML_Char*, const XML_Char*, const XML_Char*, int has_internal_subset) {
    guarded(p, [&](GuardedXmlParser& s) {
      if (has_internal_subset)
        throw InputError(s.here(), "a document type with an internal subset (entity declarations) is refused");
    });
  }
  static void XMLCALL on_entity_decl(void* p, const XML_Char* name, int, const XML_Char*, int, const XML_Char*, const XML_Char*,
                                     const XML_Char*, const XML_Char*) {
    guarded(p, [&](GuardedXmlParser& s) { throw InputError(s.here(), std::string("entity declaration '") + name + "' is refused"); });
  }
  static void XMLCALL on_skipped_entity(void* p, const XML_Char* name, int) {
    guarded(p, [&](GuardedXmlParser& s) { throw InputError(s.here(), std::string("entity reference '&") + name + ";' is refused"); });
  }
};

void GuardedXmlParser::parse_xml(const std::string& text, char namespace_separator) {
  XML_Parser parser = namespace_separator ? XML_ParserCreateNS(nullptr, namespace_separator) : XML_ParserCreate(nullptr);
  if (!parser) throw std::bad_alloc();
  parser_ = parser;
  error_ = nullptr;
  XML_SetUserData(parser, this);
  XML_SetElementHandler(parser, &Callbacks::on_start, &Callbacks::on_end);
  XML_SetCharacterDataHandler(parser, &Callbacks::on_text);
  XML_SetStartDoctypeDeclHandler(parser, &Callbacks::on_doctype);
  XML_SetEntityDeclHandler(parser, &Callbacks::on_entity_decl);
  XML_SetSkippedEntityHandler(parser, &Callbacks::on_skipped_entity);
  XML_SetParamEntityParsing(parser, XML_PARAM_ENTITY_PARSING_NEVER);
  const XML_Status status = XML_Parse(parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
  const XML_LChar* message = XML_ErrorString(XML_GetErrorCode(parser));  // null for "no error"
  const std::string xml_error = message ? message : "";
  const auto line = XML_GetCurrentLineNumber(parser), column = XML_GetCurrentColumnNumber(parser);
  XML_ParserFree(parser);
  parser_ = nullptr;
  if (error_) std::rethrow_exception(error_);
  if (status != XML_STATUS_OK)
    throw InputError(source_ + ": line " + std::to_string(line) + ", column " + std::to_string(column + 1), "XML: " + xml_error);
}

long GuardedXmlParser::current_line() const {
  return parser_ ? static_cast<long>(XML_GetCurrentLineNumber(static_cast<XML_Parser>(parser_))) : 0;
}

}  // namespace rigidfold
