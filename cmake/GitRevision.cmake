# cmake -DSOURCE_DIR=... -DOUTPUT=... -P GitRevision.cmake
# Writes OUTPUT, a C++ source defining sph::gitRevision() (core/CommandLine.hpp): the revision
# of the source tree SOURCE_DIR as `git describe --always --dirty` gives it, or "unknown" when
# SOURCE_DIR is not the top of a git checkout (a release archive, a copy inside another
# repository) or git is missing or refuses. Run at configure time and at every build
# (libraries/core/CMakeLists.txt); OUTPUT is rewritten only when the revision changed, so an
# unchanged revision recompiles nothing.
set(revision unknown)
find_package(Git QUIET)
if(GIT_FOUND)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --show-toplevel
                    OUTPUT_VARIABLE top RESULT_VARIABLE status
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(status EQUAL 0)
        file(REAL_PATH "${top}" top)
        file(REAL_PATH "${SOURCE_DIR}" source)
        if(top STREQUAL source)
            execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" describe --always --dirty
                            OUTPUT_VARIABLE described RESULT_VARIABLE status
                            OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
            if(status EQUAL 0 AND described MATCHES "^[A-Za-z0-9._/+-]+$")
                set(revision "${described}")
            endif()
        endif()
    endif()
endif()
set(content "// Made by cmake/GitRevision.cmake at build time; do not edit.
#include \"core/CommandLine.hpp\"

namespace sph
{

const char* gitRevision()
{
    return \"${revision}\";
}

} // namespace sph
")
set(old "")
if(EXISTS "${OUTPUT}")
    file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL content)
    file(WRITE "${OUTPUT}" "${content}")
endif()
