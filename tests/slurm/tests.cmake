# slurm/: scripts/slurm-render on a real single-node Slurm cluster that the test starts on the loopback
# (munged, slurmctld and slurmd from the machine's packages, with a configuration, key and state of its
# own in a temporary folder; see slurm-cluster.sh), checked frame by frame against a render without
# Slurm. Labelled `slurm`: the release run includes it, the sanitizer run (unit and gl tiers) does not.
# It needs root (slurmd starts the jobs), and is skipped, saying so, without it. It renders with 2 job
# tasks at a time, so it asks CTest for 2 processors.
add_test(NAME slurm_array_render
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/slurm-array-render-test $<TARGET_FILE:speculum>
                 ${SPECULUM_SOURCE_ROOT})
set_tests_properties(slurm_array_render PROPERTIES LABELS slurm TIMEOUT 600 SKIP_RETURN_CODE 77 PROCESSORS 2)
