# Runs one lab: its program writes the CSV files, gnuplot draws them as PNG and as SVG.
# The `labs` target and the lab's CTest test both run this script, so they do the same thing.
#
#   cmake -DPROGRAM=<lab program> -DOUTPUT_DIR=<folder> -DPLOT_SCRIPT=<plot.gp>
#         -DGNUPLOT=<gnuplot> -DCOMMON_DIR=<tutorials/common>
#         [-DIMPULSELAB=<impulselab> -DSWEEP_SCENE=<scene.json> -DSWEEP_RANGE=<from:to:step>]
#         -P run_lab.cmake
#
# With IMPULSELAB and SWEEP_SCENE the command line also sweeps the scene into sweep.csv, and the
# plot script is told so (gnuplot variable `sweep` = 1). The program's output is kept in
# summary.txt.
foreach(var IN ITEMS PROGRAM OUTPUT_DIR PLOT_SCRIPT GNUPLOT COMMON_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_lab.cmake: ${var} is not set")
  endif()
endforeach()

file(MAKE_DIRECTORY "${OUTPUT_DIR}")

execute_process(COMMAND "${PROGRAM}" "${OUTPUT_DIR}"
  OUTPUT_VARIABLE program_output
  RESULT_VARIABLE program_result)
file(WRITE "${OUTPUT_DIR}/summary.txt" "${program_output}")
message("${program_output}")
if(NOT program_result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${program_result})")
endif()

set(sweep 0)
if(IMPULSELAB AND SWEEP_SCENE)
  execute_process(COMMAND "${IMPULSELAB}" sweep "${SWEEP_SCENE}" --elasticity "${SWEEP_RANGE}"
                          --output "${OUTPUT_DIR}/sweep.csv"
    RESULT_VARIABLE sweep_result)
  if(NOT sweep_result EQUAL 0)
    message(FATAL_ERROR "impulselab sweep ${SWEEP_SCENE} failed (${sweep_result})")
  endif()
  set(sweep 1)
endif()

foreach(fmt IN ITEMS png svg)
  execute_process(
    COMMAND "${GNUPLOT}"
      -e "outdir='${OUTPUT_DIR}'; fmt='${fmt}'; common='${COMMON_DIR}'; sweep=${sweep}"
      "${PLOT_SCRIPT}"
    RESULT_VARIABLE plot_result
    ERROR_VARIABLE plot_errors)
  if(NOT plot_errors STREQUAL "")
    message("${plot_errors}")
  endif()
  if(NOT plot_result EQUAL 0)
    message(FATAL_ERROR "gnuplot ${PLOT_SCRIPT} (${fmt}) failed (${plot_result})")
  endif()
  # A warning of the script's own ("plot.gp" line 12: warning: Skipping data file with no valid
  # points) means a plot is missing something: treat it as a failure.
  if(plot_errors MATCHES "line [0-9]+: warning")
    message(FATAL_ERROR "gnuplot ${PLOT_SCRIPT} (${fmt}) warned; see above")
  endif()
endforeach()
