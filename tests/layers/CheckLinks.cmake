# cmake -DLINKS=<file> -DALLOWED=<a|b|...> -P CheckLinks.cmake
# LINKS holds a target's LINK_LIBRARIES, one list per line, as file(GENERATE) wrote them at configure
# time. Fails on any entry that is not ALLOWED: a new dependency of the GL-free core is a decision to
# make here, not a line that slips into render/CMakeLists.txt.
cmake_minimum_required(VERSION 3.25) # IN_LIST, in script mode too
file(STRINGS ${LINKS} lines)
string(REPLACE "|" ";" allowed "${ALLOWED}")
set(bad "")
foreach(line IN LISTS lines)
    foreach(entry IN LISTS line)
        # Entries linked from another directory come wrapped in ::@(directory) markers.
        if(entry STREQUAL "" OR entry MATCHES "^::@")
            continue()
        endif()
        if(NOT entry IN_LIST allowed)
            list(APPEND bad "${entry}")
        endif()
    endforeach()
endforeach()
if(bad)
    message(FATAL_ERROR "${LINKS}: links ${bad}; only ${allowed} are allowed")
endif()
message(STATUS "${LINKS}: links only ${allowed}")
