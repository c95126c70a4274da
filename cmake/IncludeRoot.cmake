# speculum_include_root(target files...): gives `target` an include root of its own, holding the headers
# among `files` (absolute paths below the source root) at their usual paths: the headers are linked
# (symlinks, at configure time) into ${CMAKE_CURRENT_BINARY_DIR}/include/<target>/. A library's sources
# then see only its own headers and those of the libraries it links, so an include that crosses a layer
# does not compile, while every #include keeps its "render/..." / "accuracy/..." spelling.
function(speculum_include_root target)
    set(root ${CMAKE_CURRENT_BINARY_DIR}/include/${target})
    file(REMOVE_RECURSE ${root}) # a header that moved away must not stay reachable
    foreach(file IN LISTS ARGN)
        if(NOT file MATCHES "\\.(h|hpp)$")
            continue()
        endif()
        file(RELATIVE_PATH relative ${SPECULUM_SOURCE_ROOT} ${file})
        get_filename_component(folder ${root}/${relative} DIRECTORY)
        file(MAKE_DIRECTORY ${folder})
        file(CREATE_LINK ${file} ${root}/${relative} SYMBOLIC)
    endforeach()
    target_include_directories(${target} PUBLIC ${root})
endfunction()
