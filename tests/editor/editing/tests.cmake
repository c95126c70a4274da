# Editing support of the document layer: property descriptions, node factory, picking, glTF export,
# crash recovery. Unit tier, no GL, no widgets.
speculum_add_test(test_editor_editing TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_properties.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_node_factory.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_picking.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_gltf_export.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_recovery.cpp
    LIBS speculum_document assimp::assimp PkgConfig::OIIO)
