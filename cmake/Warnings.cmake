# The project's warnings, as a target rather than global flags: every speculum target links
# speculum_warnings PRIVATE, so the flags apply to speculum's own sources and to nothing built from
# elsewhere, and never travel to a consumer through a PUBLIC link.
option(SPECULUM_WERROR "Treat warnings as errors (CI turns it on: SPECULUM_WERROR=1 scripts/test)" OFF)

add_library(speculum_warnings INTERFACE)
target_compile_options(speculum_warnings INTERFACE
    -Wall -Wextra -Wpedantic
    # Aggregates are routinely initialised with their leading fields only; the rest keep their defaults.
    -Wno-missing-field-initializers
    $<$<BOOL:${SPECULUM_WERROR}>:-Werror>)

# Links speculum_warnings to every target built from `directory` and below that does not link it yet,
# and names each such target: a target added without it still gets the project's warnings (and -Werror
# in CI), and the message says where the line belongs.
function(speculum_warnings_everywhere directory)
    get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
            continue()
        endif()
        get_target_property(links ${target} LINK_LIBRARIES)
        if(NOT "speculum_warnings" IN_LIST links)
            message(AUTHOR_WARNING "${target} (${directory}) does not link speculum_warnings: linked from "
                                   "the root; add `target_link_libraries(${target} PRIVATE "
                                   "speculum_warnings)`")
            target_link_libraries(${target} PRIVATE speculum_warnings)
        endif()
    endforeach()
    get_property(children DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
    foreach(child IN LISTS children)
        speculum_warnings_everywhere(${child})
    endforeach()
endfunction()
