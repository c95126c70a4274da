# GUI tier: the whole binary runs as one CTest entry under scripts/with-display (Xvfb with GLX on llvmpipe
# when there is no display). The test has its own main() (it needs a QApplication), which takes precedence
# over gtest_main's.
speculum_add_test(test_main_window TIER gui
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_main_window.cpp ${CMAKE_CURRENT_LIST_DIR}/gui_main.cpp
    LIBS speculum_ui)
