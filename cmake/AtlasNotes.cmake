# The accuracy atlas's measured notes, compiled into the programs so that
# --list-engines says what each engine was measured to do
# (utils/world/AtlasNotes.h), not what anyone claimed of it.
#
# odelab_atlas_notes(CSV TEMPLATE OUT): OUT is TEMPLATE with @ODELAB_ATLAS_ROWS@
# replaced by one C++ initializer a row of CSV (doc/atlas-report/atlas-notes.csv,
# written by lab/odelab-report --atlas: engine,setting,step,right,cases,not_right,
# no field holding a comma) and @ODELAB_ATLAS_MADE@ by its "# date:" and
# "# commit:" lines. A tree without the CSV gets an empty table.
#
# The CMake builds call it at configure time; Makefile.win runs this file as a
# script: cmake -DCSV=... -DTEMPLATE=... -DOUT=... -P cmake/AtlasNotes.cmake

function(odelab_atlas_notes csv template out)
  set(ODELAB_ATLAS_ROWS "")
  set(ODELAB_ATLAS_MADE "")
  if(EXISTS "${csv}")
    file(STRINGS "${csv}" _lines ENCODING UTF-8)
    set(_header TRUE)
    foreach(_line IN LISTS _lines)
      if(_line MATCHES "^# (date|commit): (.*)$")
        string(APPEND ODELAB_ATLAS_MADE "${CMAKE_MATCH_1} ${CMAKE_MATCH_2}; ")
      elseif(_line MATCHES "^#" OR _line STREQUAL "")
      elseif(_header)
        if(NOT _line STREQUAL "engine,setting,step,right,cases,not_right")
          message(FATAL_ERROR "${csv}: its columns are '${_line}', not engine,setting,step,right,cases,not_right")
        endif()
        set(_header FALSE)
      else()
        string(REPLACE "\\" "\\\\" _line "${_line}")
        string(REPLACE "\"" "\\\"" _line "${_line}")
        string(REPLACE ";" "\\;" _escaped "${_line}")  # not_right's "; " is text, not a list
        string(REPLACE "," ";" _cells "${_escaped}")
        list(LENGTH _cells _count)
        if(NOT _count EQUAL 6)
          message(FATAL_ERROR "${csv}: the row '${_line}' has ${_count} cells, not 6")
        endif()
        list(GET _cells 0 _engine)
        list(GET _cells 1 _setting)
        list(GET _cells 2 _step)
        list(GET _cells 3 _right)
        list(GET _cells 4 _cases)
        list(GET _cells 5 _not_right)
        if(NOT _right MATCHES "^[0-9]+$" OR NOT _cases MATCHES "^[0-9]+$")
          message(FATAL_ERROR "${csv}: the row '${_line}' has counts that are not whole numbers")
        endif()
        string(APPEND ODELAB_ATLAS_ROWS
               "      {\"${_engine}\", \"${_setting}\", \"${_step}\", ${_right}, ${_cases}, \"${_not_right}\"},\n")
      endif()
    endforeach()
    string(REGEX REPLACE "; $" "" ODELAB_ATLAS_MADE "${ODELAB_ATLAS_MADE}")
    string(REPLACE "\"" "\\\"" ODELAB_ATLAS_MADE "${ODELAB_ATLAS_MADE}")
  endif()
  configure_file("${template}" "${out}" @ONLY)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  foreach(_variable CSV TEMPLATE OUT)
    if(NOT DEFINED ${_variable})
      message(FATAL_ERROR "AtlasNotes.cmake: -D${_variable}=... is missing")
    endif()
  endforeach()
  odelab_atlas_notes("${CSV}" "${TEMPLATE}" "${OUT}")
endif()
