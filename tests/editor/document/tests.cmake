# editor/document: undo commands and exact undo, the document session, editing operations in
# transactions and where new things land, the node factory, the inspector's properties and limits,
# applying bench results. Unit tier, no GL, no widgets.
find_package(Qt6 REQUIRED COMPONENTS Test) # QSignalSpy
speculum_add_test(EditorDocumentTest TIER unit
    SOURCES CommandsTest.cpp CommandsExactUndoTest.cpp DocumentSessionTest.cpp EditOperationsTest.cpp
            EditOperationsPlacementTest.cpp EditTransactionTest.cpp NodeFactoryTest.cpp PropertiesTest.cpp
            PropertiesLimitsTest.cpp SweepResultsTest.cpp SweepResultsUndoTest.cpp
    LIBS speculum_editor_document Qt6::Test)
