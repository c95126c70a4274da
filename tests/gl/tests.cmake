speculum_add_test(test_gl_shadows TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_shadows.cpp ${CMAKE_CURRENT_LIST_DIR}/test_frame.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_mirrors.cpp ${CMAKE_CURRENT_LIST_DIR}/test_lighting_variants.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_mirror_occlusion.cpp ${CMAKE_CURRENT_LIST_DIR}/test_back_face_culling.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_resolution_scale.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio speculum_editor_document speculum_scene_export PkgConfig::OIIO)
speculum_add_test(test_gl_reflector TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reflector.cpp ${CMAKE_CURRENT_LIST_DIR}/test_frame_report.cpp
            ${CMAKE_CURRENT_LIST_DIR}/test_reflector_fill.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
# Stills in tiles (compared with untiled stills) and the GPU's size limits.
speculum_add_test(test_gl_stills TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_tiled_stills.cpp ${CMAKE_CURRENT_LIST_DIR}/test_gpu_limits.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio speculum_editor_document speculum_scene_export)
# Textures (which way up, wrap modes, 16-bit) and model-file materials (vertex colours, alpha masks and
# their shadows, normal maps, emission textures) in the rasterizer, and its agreement with the tracer.
speculum_add_test(test_gl_materials TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_materials.cpp
            ${CMAKE_CURRENT_LIST_DIR}/reference/test_material_agreement.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio PkgConfig::OIIO)
# A glTF quad read through the editor's model import shows its texture upright in both renderers.
speculum_add_test(test_gl_imported_orientation TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_imported_orientation.cpp
    LIBS speculum_editor_document speculum_scene_export speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio PkgConfig::OIIO)
# Values at the limits of SceneLimits.hpp render finite and agree with the tracer; values beyond, finite.
speculum_add_test(test_gl_extreme_values TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_extreme_values.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio PkgConfig::OIIO)
# GPU allocations that do not fit (shadow maps, environment maps, render targets): drawn smaller, warned.
speculum_add_test(test_gl_gpu_allocation TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gpu_allocation.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
# The same with real 8192 reflectors drawn at the size the driver holds (seconds each on llvmpipe).
speculum_add_test(test_gl_gpu_allocation_slow TIER gl LABELS slow
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_gpu_allocation.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
target_compile_definitions(test_gl_gpu_allocation_slow PRIVATE SPECULUM_SLOW_ALLOCATION_TESTS=1)
# The camera's colour buffer: 8-bit sRGB where nothing needs half float, the same image as the half-float
# buffer and its composite (demos and scenes made to tell them apart), float stills linear.
speculum_add_test(test_gl_camera_buffer TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_camera_buffer.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio speculum_editor_document speculum_scene_export)
# Big meshes in reflections: the mirrors' views draw the simplified level the plan names, the camera's
# view every triangle.
speculum_add_test(test_gl_reflected_detail TIER gl
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_reflected_detail.cpp
    LIBS speculum_render_renderer speculum_render_reference speculum_render_metrics speculum_render_imageio)
