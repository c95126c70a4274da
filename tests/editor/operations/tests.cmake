# The document layer's editing operations, each one undo step in an EditTransaction, and the document
# session (scene, history and mesh library replaced together). Unit tier, no GL, no widgets.
speculum_add_test(test_editor_operations TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_edit_transaction.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_edit_operations.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_document_session.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_placement.cpp
    LIBS speculum_editor_document speculum_scene_export)
