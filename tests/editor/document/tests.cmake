# editor/document: undo commands and exact undo, the document session, editing operations in
# transactions and where new things land, copy and paste, the node factory, the inspector's properties and limits,
# applying bench results. Unit tier, no GL, no widgets.
find_package(Qt6 REQUIRED COMPONENTS Test) # QSignalSpy
speculum_add_test(EditorDocumentTest TIER unit
    SOURCES CommandsTest.cpp CommandsExactUndoTest.cpp DocumentSessionTest.cpp EditOperationsTest.cpp
            EditOperationsPlacementTest.cpp EditTransactionTest.cpp NodeFactoryTest.cpp PropertiesTest.cpp
            PropertiesLimitsTest.cpp SweepResultsTest.cpp SweepResultsUndoTest.cpp NodeClipboardTest.cpp
    LIBS speculum_editor_document Qt6::Test)

# Adding a field to a declaration is enough for it to be read, written, shown, hashed and swept: this
# program is built against copies of the libraries that see render/frame, compiled with a planar mirror
# that has one more field (SPECULUM_FIELD_PROBE in render/frame/Mirror.hpp).
speculum_library_variants(SUFFIX _probe DEFINITIONS SPECULUM_FIELD_PROBE
                          FOR speculum_editor_document SEES speculum_render_frame)
speculum_add_test(FieldDeclarationTest TIER unit
    SOURCES FieldDeclarationTest.cpp
    LIBS speculum_editor_document_probe)
