# ui/'s imports run one way: a file includes headers of its own folder and of folders on lower floors only
# (docs/architecture.md, "The studio (ui/)"). Run as `cmake -DUI_DIR=<ui folder> -P check_ui_layers.cmake`;
# fails naming every include that runs up a floor.
#
# Floors, bottom first; "top" is ui/ itself (MainWindow and the studio's start-up).
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
set(floors "common;document" "viewer" "jobs" "edit" "panels;device" "project" "slicing" "top")
# Imports that still run up, each with why; the check fails on any other, and on one of these that is gone (so
# the list cannot go stale). ProjectSession and SliceSession still take the MainWindow they serve.
set(known_upward
  "project/project_session.cpp -> top/main_window.h"
  "slicing/slice_session.cpp -> top/main_window.h")

if(NOT UI_DIR)
  message(FATAL_ERROR "UI_DIR is not set: pass -DUI_DIR=<the ui folder>")
endif()

function(floor_of folder out)
  set(index 0)
  foreach(floor IN LISTS floors)
    string(REPLACE ";" "|" names "${floor}")
    if(folder MATCHES "^(${names})$")
      set(${out} ${index} PARENT_SCOPE)
      return()
    endif()
    math(EXPR index "${index} + 1")
  endforeach()
  set(${out} -1 PARENT_SCOPE)
endfunction()

# "viewer/plan_scene.cpp" -> "viewer"; "main_window.cpp" -> "top".
function(folder_of relative out)
  if(relative MATCHES "^([a-z_]+)/")
    set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  else()
    set(${out} "top" PARENT_SCOPE)
  endif()
endfunction()

file(GLOB_RECURSE sources RELATIVE "${UI_DIR}" "${UI_DIR}/*.h" "${UI_DIR}/*.cpp")
set(problems "")
set(seen_known "")
foreach(source IN LISTS sources)
  folder_of("${source}" from)
  floor_of("${from}" from_floor)
  if(from_floor EQUAL -1)
    string(APPEND problems "\n  ${source}: the folder ${from} has no floor (add it to check_ui_layers.cmake and docs/architecture.md)")
    continue()
  endif()
  file(STRINGS "${UI_DIR}/${source}" includes REGEX "^#include \"ui/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"ui/([^\"]+)\".*" "\\1" target "${line}")
    folder_of("${target}" to)
    floor_of("${to}" to_floor)
    if(to_floor GREATER from_floor)
      get_filename_component(name "${target}" NAME)
      set(edge "${source} -> ${to}/${name}")
      if(edge IN_LIST known_upward)
        list(APPEND seen_known "${edge}")
      else()
        string(APPEND problems "\n  ${source} includes ui/${target}: ${from} is below ${to}")
      endif()
    endif()
  endforeach()
endforeach()
foreach(edge IN LISTS known_upward)
  if(NOT edge IN_LIST seen_known)
    string(APPEND problems "\n  ${edge} no longer runs up: remove it from known_upward")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "ui/ imports that run up a floor:${problems}")
endif()
message(STATUS "ui/ imports run one way.")
