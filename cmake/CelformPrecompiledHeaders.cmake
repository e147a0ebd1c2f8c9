# Precompiled headers. Most of a cold build's time goes to parsing the same Qt, Eigen and standard
# headers in every file: <QtTest/QtTest> alone takes 5 s per file on a CI core, <Eigen/Geometry>
# 1.5 s. Each library target precompiles the headers most of its files include, and tests and
# benchmarks that link the same libraries share one precompiled header (REUSE_FROM), so the parse
# happens once per library and once per group of alike tests instead of once per file.
#
# A precompiled header is only valid for files compiled with the owner's flags and definitions;
# that is why tests are grouped by what they link (the definitions come from the linked targets).
# Files with their own compile options skip it (SKIP_PRECOMPILE_HEADERS).
option(CELFORM_PRECOMPILE_HEADERS "Precompile the headers most files of a target include" ON)

set(CELFORM_PCH_STD
  <algorithm> <array> <cmath> <cstdint> <cstring> <functional> <limits> <map> <memory> <optional>
  <string> <utility> <vector>)
set(CELFORM_PCH_EIGEN <Eigen/Core> <Eigen/Geometry>)
set(CELFORM_PCH_QT_CORE
  <QCoreApplication> <QDir> <QFile> <QFileInfo> <QJsonArray> <QJsonDocument> <QJsonObject>
  <QObject> <QString> <QStringList>)
set(CELFORM_PCH_QT_GUI <QImage>)
set(CELFORM_PCH_QT_WIDGETS
  <QAction> <QApplication> <QComboBox> <QDockWidget> <QDoubleSpinBox> <QHBoxLayout> <QLabel>
  <QPainter> <QPushButton> <QSpinBox> <QUndoStack> <QVBoxLayout> <QWidget>)

# celform_precompile(TARGET HEADER...): TARGET's own precompiled header.
function(celform_precompile target)
  if(CELFORM_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# celform_precompile_group(TARGET KEY HEADER...): TARGET joins the group KEY (targets that link
# the same libraries with the same definitions). celform_precompile_groups() gives every group of
# two or more one precompiled header made from HEADER... (the first member's list).
function(celform_precompile_group target key)
  if(NOT CELFORM_PRECOMPILE_HEADERS)
    return()
  endif()
  # The generated, moc-less file of an AUTOMOC target holds one line: loading the header would cost
  # more than the file.
  set_source_files_properties(${CMAKE_CURRENT_BINARY_DIR}/${target}_autogen/mocs_compilation.cpp
    PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
  string(MD5 _id "${key}")
  get_property(_groups GLOBAL PROPERTY CELFORM_PCH_GROUPS)
  if(NOT _id IN_LIST _groups)
    set_property(GLOBAL APPEND PROPERTY CELFORM_PCH_GROUPS ${_id})
    set_property(GLOBAL PROPERTY CELFORM_PCH_HEADERS_${_id} ${ARGN})
  endif()
  set_property(GLOBAL APPEND PROPERTY CELFORM_PCH_MEMBERS_${_id} ${target})
endfunction()

function(celform_precompile_groups)
  get_property(_groups GLOBAL PROPERTY CELFORM_PCH_GROUPS)
  foreach(_id IN LISTS _groups)
    get_property(_members GLOBAL PROPERTY CELFORM_PCH_MEMBERS_${_id})
    list(LENGTH _members _count)
    if(_count LESS 2)
      continue()
    endif()
    get_property(_headers GLOBAL PROPERTY CELFORM_PCH_HEADERS_${_id})
    list(POP_FRONT _members _owner)
    target_precompile_headers(${_owner} PRIVATE ${_headers})
    foreach(_member IN LISTS _members)
      target_precompile_headers(${_member} REUSE_FROM ${_owner})
    endforeach()
  endforeach()
endfunction()
