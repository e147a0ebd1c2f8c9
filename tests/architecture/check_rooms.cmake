# Checks which room of the code includes which (docs/architecture.md): run as
#   cmake -DSOURCE_DIR=<checkout> -P tests/architecture/check_rooms.cmake
# Each rule names a room (a folder) and the includes it must not have. The link step catches most
# of these too (a room's library does not link what it must not use); this check also covers
# rooms that share a library and headers whose use would not need a symbol.
cmake_minimum_required(VERSION 3.25)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "SOURCE_DIR is not set")
endif()

set(M "celform/model")
set(V "celform/views")
# check(ROOM FORBIDDEN WHY): no file below ROOM (relative to SOURCE_DIR) includes a path matching
# the regular expression FORBIDDEN; WHY says what the wall is for.
set(violations "")
set(rule_count 0)
function(check room forbidden why)
  math(EXPR n "${rule_count} + 1")
  set(rule_count ${n} PARENT_SCOPE)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/${room}")
    set(violations ${violations} "room ${room} does not exist (a rule names it)" PARENT_SCOPE)
    return()
  endif()
  file(GLOB_RECURSE files "${SOURCE_DIR}/${room}/*.h" "${SOURCE_DIR}/${room}/*.cpp" "${SOURCE_DIR}/${room}/*.h.in")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*$" "\\1" included "${line}")
      if(included MATCHES "${forbidden}")
        file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
        list(APPEND violations "${rel} includes ${included}: ${why}")
      endif()
    endforeach()
  endforeach()
  set(violations ${violations} PARENT_SCOPE)
endfunction()

check("algorithms"
  "^(Q[A-Za-z]+|Qt[A-Za-z]*/.*|vtk.*|OpenImageIO/.*|celform/(model|views)/.*)$"
  "algorithms are plain C++17: no Qt, VTK or OpenImageIO, nothing above them")
check("model"
  "^(vtk.*|QtWidgets/.*|QWidget|QMainWindow|QDialog|QOpenGLWidget|celform/views/.*|cli/.*|editor/.*|launcher/.*)$"
  "the model has no widgets, no VTK and nothing of views/ or app/")
check("model/${M}/data"
  "^${M}/(io|document|render|analysis|export)/"
  "data/ is the bottom room of the model")
check("model/${M}/io"
  "^${M}/(document|render|analysis|export)/"
  "io/ reads and writes data; it knows no document and no pipeline")
check("model/${M}/document"
  "^${M}/(render|analysis|export)/"
  "the document never includes the pipeline: long solves return a result the document applies")
check("model/${M}/render"
  "^${M}/(document|export)/"
  "render/ works on the data, not on the document")
check("model/${M}/analysis"
  "^${M}/(document|export)/"
  "analysis/ works on the data, not on the document")
check("model/${M}/export"
  "^${M}/document/"
  "export/ works on the data, not on the document")
check("views"
  "^(cli|editor|launcher)/"
  "views never include app/")
check("views/${V}/timeline"
  "^${V}/(viewport|tools|overlays|panels)/"
  "the timeline knows the document only")
check("views/${V}/overlays"
  "^${V}/(panels|timeline|tools)/"
  "overlays draw over the viewport; panels and tools are above them")
check("views/${V}/tools"
  "^${V}/(panels|timeline)/"
  "tools talk to the viewport, not to the docks")
check("views/${V}/panels" "^${V}/tools/" "panels edit the document; tools belong to the viewport")
check("views/${V}/viewport"
  "^${V}/(panels|timeline)/"
  "the viewport does not know the docks")
check("app/cli"
  "^(${V}/.*|editor/.*|launcher/.*|vtk.*|QWidget|QtWidgets/.*)$"
  "the command line links the model only")
check("app/python"
  "^(${V}/.*|editor/.*|vtk.*|QWidget|QtWidgets/.*|QGuiApplication)$"
  "the Python module runs headless: the model and the command line's code only")
check("app/launcher"
  "^(${V}/.*|editor/.*|vtk.*|QWidget|QtWidgets/.*)$"
  "the launcher loads the editor module; it links no widgets")

if(violations)
  list(LENGTH violations count)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "${count} include(s) cross a room's wall:\n  ${text}")
endif()
message(STATUS "rooms: ${rule_count} rules hold")
