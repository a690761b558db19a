# Writes OUT (a C++ header) with the project version and the git commit of SOURCE_DIR, run at
# build time (not configure time) so that the commit a binary reports is the one it was built
# from. The header is rewritten only when its text changes, so an unchanged tree rebuilds nothing.
# -D VERSION=... -D SOURCE_DIR=... -D OUT=...
set(commit "unknown")
find_program(GIT_PROGRAM git)
if(GIT_PROGRAM AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_PROGRAM}" -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                  OUTPUT_VARIABLE described OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE described_status ERROR_QUIET)
  if(described_status EQUAL 0 AND described)
    set(commit "${described}")
  endif()
endif()
set(text "#pragma once
// Generated at build time by cmake/write_version_header.cmake: do not edit.
namespace rigidfold {
inline constexpr const char* kRigidfoldVersion = \"${VERSION}\";
// git describe --always --dirty of the source tree when this binary was built (\"unknown\"
// outside a git checkout); \"-dirty\": built with uncommitted changes.
inline constexpr const char* kRigidfoldCommit = \"${commit}\";
}  // namespace rigidfold
")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
else()
  set(old "")
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
