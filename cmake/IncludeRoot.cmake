# speculum_include_root(target files...): gives `target` an include root of its own, holding the headers
# among `files` (absolute paths below the source root) at their usual paths: the headers are linked
# (symlinks, at configure time) into ${CMAKE_BINARY_DIR}/include/<target>/. A library's sources then see
# only its own headers and those of the libraries it links, so an include that crosses a layer does not
# compile, while every #include keeps its "render/..." / "scene/..." spelling.
function(speculum_include_root target)
    set(root ${CMAKE_BINARY_DIR}/include/${target})
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
    file(MAKE_DIRECTORY ${root})
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY")
        target_include_directories(${target} INTERFACE ${root})
    else()
        target_include_directories(${target} PUBLIC ${root})
    endif()
endfunction()
