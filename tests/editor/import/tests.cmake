# Model import through Assimp (real files from Debian's assimp-testmodels, broken files written by the
# tests): unit tier, no GL. Links Assimp directly to cross-check the flattening against its own
# PreTransformVertices step.
speculum_add_test(test_editor_import TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_model_import.cpp
    LIBS speculum_editor_document speculum_scene_export assimp::assimp)
# Every file of the corpus in a child process of its own under a time limit (a hang or a crash fails
# naming the file); fork() needs no other thread running, so it is a binary of its own.
speculum_add_test(test_editor_import_corpus TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_import_corpus.cpp
    LIBS speculum_editor_document speculum_scene_export)
# Parts, materials, textures, node tree and units kept from the file (issue 13).
speculum_add_test(test_editor_import_parts TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_model_parts.cpp
    LIBS speculum_editor_document speculum_scene_export)
# Hostile model files (issue 14): node-graph DAGs and cycles, deep nesting, bogus declared counts under
# another name, FIFOs and devices as the model or a file it references; each import in a child process
# under a time and memory limit, so a regression fails rather than hangs.
speculum_add_test(test_editor_import_hostile TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_hostile_models.cpp
    LIBS speculum_editor_document speculum_scene_export)
# The read in a child process: Assimp crashing, hanging (CPU limit) or cancelled mid-read is a one-line
# refusal naming the file and leaves no child behind; what the child sends equals the in-process import;
# the stream between them round-trips every field and refuses a truncated one.
speculum_add_test(test_editor_import_child TIER unit
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_import_child.cpp
    LIBS speculum_editor_document speculum_scene_export)
