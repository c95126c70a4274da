# speculum_library(FOLDER [PROGRAM name] [PUBLIC targets...] [PRIVATE targets...])
#
# The library of one source folder (folder = target): speculum_<FOLDER with '/' as '_'>, built from every
# .cpp and .hpp directly in FOLDER (relative to the source root), with an include root of its own
# (cmake/IncludeRoot.cmake) so that its sources see only their own headers and those of the libraries
# they link. A folder without a .cpp gives an INTERFACE library. Every library links speculum_warnings.
#
# These calls are the one statement of the layers: which folder may use which is what each links.
# speculum_write_library_graph() writes them out for the checks in tests/layers.
function(speculum_library folder)
    cmake_parse_arguments(ARG "" "PROGRAM" "PUBLIC;PRIVATE" ${ARGN})
    string(REPLACE "/" "_" name "speculum_${folder}")
    if(ARG_PROGRAM)
        set(name ${ARG_PROGRAM})
    endif()
    file(GLOB files CONFIGURE_DEPENDS ${SPECULUM_SOURCE_ROOT}/${folder}/*.cpp
         ${SPECULUM_SOURCE_ROOT}/${folder}/*.hpp)
    set(sources ${files})
    list(FILTER sources INCLUDE REGEX "\\.cpp$")
    if(ARG_PROGRAM)
        add_executable(${name} ${files})
        speculum_include_root(${name} ${files})
        target_link_libraries(${name} PRIVATE ${ARG_PUBLIC} ${ARG_PRIVATE} speculum_warnings)
    elseif(sources)
        add_library(${name} STATIC ${files})
        speculum_include_root(${name} ${files})
        target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE} speculum_warnings)
    else()
        add_library(${name} INTERFACE ${files})
        speculum_include_root(${name} ${files})
        target_link_libraries(${name} INTERFACE ${ARG_PUBLIC} ${ARG_PRIVATE})
    endif()
    set_property(GLOBAL APPEND PROPERTY SPECULUM_LIBRARIES ${name})
    string(REPLACE ";" " " public "${ARG_PUBLIC}")
    string(REPLACE ";" " " private "${ARG_PRIVATE}")
    set_property(GLOBAL APPEND_STRING PROPERTY SPECULUM_LIBRARY_GRAPH
                 "${name} ${folder} public: ${public} private: ${private}\n")
endfunction()

# Writes ${CMAKE_BINARY_DIR}/libraries.txt: one line per speculum_library, "target folder public: ...
# private: ...", naming the targets (speculum's and outside ones) each links.
function(speculum_write_library_graph)
    get_property(graph GLOBAL PROPERTY SPECULUM_LIBRARY_GRAPH)
    file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/libraries.txt CONTENT "${graph}")
endfunction()
