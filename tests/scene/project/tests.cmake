# scene/project: project files read (every error, the limits, materials), written, round-tripped, saved
# onto a full disk, and crash-recovery files. Unit tier. OpenImageIO for support/FillingDisk.hpp.
speculum_add_test(SceneProjectTest TIER unit
    SOURCES ProjectFileTest.cpp ProjectFileErrorsTest.cpp ProjectFileLimitsTest.cpp ProjectFileMaterialsTest.cpp
            ProjectFileRoundTripTest.cpp ProjectFileSaveFailuresTest.cpp RecoveryTest.cpp
    LIBS speculum_scene_project PkgConfig::OIIO speculum_editor_document)
