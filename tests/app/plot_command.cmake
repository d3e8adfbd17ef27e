# `rugosim plot` end to end: simulate tests/app/plot_scene.json into WORK_DIR, then plot its CSVs.
# Usage: cmake -DPROGRAM=<rugosim> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -DCASE=<case>
#              -P plot_command.cmake
# CASE:
#   draws         both PNGs (and each alone, and --bodies with a quoted name): exit 0, real PNGs
#                 of a few KB, no temporary file left
#   bad_csv       a wrong header, a wrong field count, a field that is not a number, an unclosed
#                 quote, a missing file: exit 2, stderr names the file and line, no PNG
#   unknown_body  --bodies with a name not in the trajectory: exit 2 and the known bodies listed
#   no_gnuplot    gnuplot not on PATH: exit 1, a message naming gnuplot, no PNG
cmake_policy(VERSION 3.25)

set(failures "")
macro(fail text)
  string(APPEND failures "  ${text}\n")
endmacro()

# Runs `rugosim ARGN`, leaving the exit code in `code` and stderr in `err`.
function(run_program)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE stderr)
  set(code "${rc}" PARENT_SCOPE)
  set(err "${out}${stderr}" PARENT_SCOPE)
endfunction()

# Fails unless the folder holds no PNG and no temporary file.
function(expect_nothing_in dir what)
  file(GLOB left "${dir}/*.png" "${dir}/.*tmp*")
  if(left)
    set(failures "${failures}  ${what}: left ${left}\n" PARENT_SCOPE)
  endif()
endfunction()

function(expect_png path what)
  if(NOT EXISTS "${path}")
    set(failures "${failures}  ${what}: ${path} was not written\n" PARENT_SCOPE)
    return()
  endif()
  file(READ "${path}" signature LIMIT 8 HEX)
  file(SIZE "${path}" size)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    set(failures "${failures}  ${what}: ${path} is not a PNG (starts ${signature})\n" PARENT_SCOPE)
  elseif(size LESS 5000)
    set(failures "${failures}  ${what}: ${path} is only ${size} bytes\n" PARENT_SCOPE)
  endif()
endfunction()

if(CASE STREQUAL "draws")
  find_program(GNUPLOT gnuplot)
  if(NOT GNUPLOT)
    message(FATAL_ERROR "gnuplot is not installed: `rugosim plot` needs it on PATH (Debian "
                        "package gnuplot-nox; cmake/install-deps.sh installs it)")
  endif()
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(trajectory "${WORK_DIR}/trajectory.csv")
set(events "${WORK_DIR}/events.csv")
run_program("${PROGRAM}" simulate "${SOURCE_DIR}/tests/app/plot_scene.json"
            --trajectory "${trajectory}" --events "${events}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "rugosim simulate tests/app/plot_scene.json: exit ${code}\n${err}")
endif()
file(STRINGS "${events}" collisions REGEX ",collision,")
if(NOT collisions)
  message(FATAL_ERROR "the test scene produced no collision: ${events}")
endif()

if(CASE STREQUAL "draws")
  set(out "${WORK_DIR}/plots")
  run_program("${PROGRAM}" plot --events "${events}" --trajectory "${trajectory}" -o "${out}")
  if(NOT code EQUAL 0)
    fail("plot of both files: exit ${code}, expected 0:\n${err}")
  endif()
  expect_png("${out}/friction.png" "plot of both files")
  expect_png("${out}/velocity.png" "plot of both files")
  file(GLOB temporaries "${out}/.*tmp*")
  if(temporaries)
    fail("plot of both files left ${temporaries}")
  endif()

  # Each input alone draws only its own figure.
  run_program("${PROGRAM}" plot --events "${events}" -o "${WORK_DIR}/events_only" --no-contacts)
  expect_png("${WORK_DIR}/events_only/friction.png" "events only")
  if(NOT code EQUAL 0 OR EXISTS "${WORK_DIR}/events_only/velocity.png")
    fail("events only: exit ${code}, or a velocity.png was drawn:\n${err}")
  endif()
  run_program("${PROGRAM}" plot --trajectory "${trajectory}" -o "${WORK_DIR}/trajectory_only"
              --bodies "pebble, \"disk, small\"")
  expect_png("${WORK_DIR}/trajectory_only/velocity.png" "trajectory only, two bodies chosen")
  if(NOT code EQUAL 0 OR EXISTS "${WORK_DIR}/trajectory_only/friction.png")
    fail("trajectory only: exit ${code}, or a friction.png was drawn:\n${err}")
  endif()

elseif(CASE STREQUAL "bad_csv")
  file(READ "${events}" events_text)
  file(READ "${trajectory}" trajectory_text)
  # A wrong header: one column renamed.
  string(REPLACE "lambda_b,mu,vn" "lambda_b,friction,vn" text "${events_text}")
  file(WRITE "${WORK_DIR}/bad_header.csv" "${text}")
  # Line 3 (the second body's first row) loses its last field.
  string(REGEX REPLACE "\n(0,0,\"disk, small\",[^\n]*),[^,\n]*\n" "\n\\1\n" text
                       "${trajectory_text}")
  file(WRITE "${WORK_DIR}/bad_count.csv" "${text}")
  # Line 4 (frame 1 of the first body) gets a word for its time.
  string(REGEX REPLACE "\n1,[^,\n]*,pebble," "\n1,soon,pebble," text "${trajectory_text}")
  file(WRITE "${WORK_DIR}/bad_number.csv" "${text}")
  file(WRITE "${WORK_DIR}/bad_quote.csv"
       "frame,time,body,x,y,angle,vx,vy,omega,kinetic_energy\n0,0,pebble,0,0,0,0,0,0,0\n"
       "0,0,\"disk,0,0,0,0,0,0,0\n")
  set(cases
      "--events|bad_header.csv|bad_header.csv:1: expected the events.csv header"
      "--trajectory|bad_count.csv|bad_count.csv:3: expected 10 fields"
      "--trajectory|bad_number.csv|bad_number.csv:4: column time (field 2): expected a number"
      "--trajectory|bad_quote.csv|bad_quote.csv:3: a quoted field"
      "--events|no_such_file.csv|no_such_file.csv: cannot read")
  foreach(entry IN LISTS cases)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 0 option)
    list(GET parts 1 name)
    list(GET parts 2 expected)
    set(out "${WORK_DIR}/out_${name}")
    # The other input is good: nothing at all is drawn when either is bad.
    if(option STREQUAL "--events")
      set(other --trajectory "${trajectory}")
    else()
      set(other --events "${events}")
    endif()
    run_program("${PROGRAM}" plot ${option} "${WORK_DIR}/${name}" ${other} -o "${out}")
    if(NOT code EQUAL 2)
      fail("${name}: exit ${code}, expected 2:\n${err}")
    endif()
    string(FIND "${err}" "${expected}" at)
    if(at EQUAL -1)
      fail("${name}: stderr lacks \"${expected}\":\n${err}")
    endif()
    expect_nothing_in("${out}" "${name}")
  endforeach()
  run_program("${PROGRAM}" plot -o "${WORK_DIR}/out_no_input")
  if(NOT code EQUAL 2)
    fail("no --events and no --trajectory: exit ${code}, expected 2:\n${err}")
  endif()

elseif(CASE STREQUAL "unknown_body")
  set(out "${WORK_DIR}/plots")
  run_program("${PROGRAM}" plot --events "${events}" --trajectory "${trajectory}" -o "${out}"
              --bodies "pebble,boulder")
  if(NOT code EQUAL 2)
    fail("--bodies pebble,boulder: exit ${code}, expected 2:\n${err}")
  endif()
  foreach(expected "no body boulder" "pebble, \"disk, small\"")
    string(FIND "${err}" "${expected}" at)
    if(at EQUAL -1)
      fail("--bodies pebble,boulder: stderr lacks ${expected}:\n${err}")
    endif()
  endforeach()
  expect_nothing_in("${out}" "--bodies pebble,boulder")

elseif(CASE STREQUAL "no_gnuplot")
  set(out "${WORK_DIR}/plots")
  run_program("${CMAKE_COMMAND}" -E env "PATH=${WORK_DIR}/no_programs_here" "${PROGRAM}" plot
              --events "${events}" --trajectory "${trajectory}" -o "${out}")
  if(NOT code EQUAL 1)
    fail("without gnuplot: exit ${code}, expected 1:\n${err}")
  endif()
  string(FIND "${err}" "cannot run gnuplot" at)
  if(at EQUAL -1)
    fail("without gnuplot: stderr lacks \"cannot run gnuplot\":\n${err}")
  endif()
  expect_nothing_in("${out}" "without gnuplot")

else()
  message(FATAL_ERROR "unknown CASE \"${CASE}\"")
endif()

if(failures)
  message(FATAL_ERROR "rugosim plot, ${CASE} (files kept in ${WORK_DIR}):\n${failures}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
message(STATUS "rugosim plot, ${CASE}: as expected")
