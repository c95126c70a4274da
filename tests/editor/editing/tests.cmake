# Editing support of the document layer: property descriptions, node factory, picking, glTF export,
# crash recovery, exact undo, the limits the reader and the inspector share. Unit tier, no GL, no widgets.
find_package(Qt6 REQUIRED COMPONENTS Test) # QSignalSpy
speculum_add_test(test_editor_editing TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_properties.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_node_factory.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_picking.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_gltf_export.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_recovery.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_exact_undo.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_sweep_undo.cpp
    LIBS speculum_editor_document speculum_scene_export assimp::assimp PkgConfig::OIIO Qt6::Test)
# The handle-drag state machine (editor/ui/HandleDrag): plain mouse positions and the handles as the view
# camera sets them up, no widget and no display, so it is unit tier although it lives in the UI library.
speculum_add_test(test_handle_drag TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_handle_drag.cpp
    LIBS speculum_editor_ui)
