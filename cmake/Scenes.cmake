# The scenes' registration, tests/scenes/scenes.txt, read for a CMake build
# (the desktop's and the browser's).
#
# odelab_read_scenes(ROOT): sets ODELAB_SCENE_NAMES (test0 ... in the list's
# order) and, for each NAME, ODELAB_SCENE_SOURCE_<NAME> (its source's path)
# and ODELAB_SCENE_TITLE_<NAME>; a malformed line, a name given twice or a
# source that is not there stops the configuration, naming the line.
# odelab_scene_definitions(NAME): the compile definitions its source needs
# (ODELAB_SCENE_NAME, ODELAB_SCENE_TITLE: see utils/SceneRegistry.h).
# odelab_write_scene_list(FILE): the list as JSON ([{"name", "title"}]), for
# the web page's menu.
macro(odelab_read_scenes root)
  set(_list "${root}/tests/scenes/scenes.txt")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_list}")
  file(STRINGS "${_list}" _lines ENCODING UTF-8)
  set(ODELAB_SCENE_NAMES)
  set(_number 0)
  foreach(_line IN LISTS _lines)
    math(EXPR _number "${_number} + 1")
    if(_line MATCHES "^[ \t]*(#.*)?$")
      continue()
    endif()
    if(NOT _line MATCHES "^([a-z][a-z0-9_]*)[ \t]+([A-Za-z0-9_.-]+\\.cpp)[ \t]+([^\t\"\\\\;]*[^ \t\"\\\\;])[ \t]*$")
      message(FATAL_ERROR "${_list}:${_number}: \"${_line}\" is not NAME SOURCE.cpp TITLE "
                          "(a lower-case name, a source in tests/scenes/, a title without quotes, backslashes or ;)")
    endif()
    set(_name ${CMAKE_MATCH_1})
    list(FIND ODELAB_SCENE_NAMES ${_name} _seen)
    if(_seen GREATER -1)
      message(FATAL_ERROR "${_list}:${_number}: the scene ${_name} is listed twice")
    endif()
    if(NOT EXISTS "${root}/tests/scenes/${CMAKE_MATCH_2}")
      message(FATAL_ERROR "${_list}:${_number}: ${CMAKE_MATCH_2} is not in tests/scenes/")
    endif()
    list(APPEND ODELAB_SCENE_NAMES ${_name})
    set(ODELAB_SCENE_SOURCE_${_name} "${root}/tests/scenes/${CMAKE_MATCH_2}")
    set(ODELAB_SCENE_TITLE_${_name} "${CMAKE_MATCH_3}")
  endforeach()
  if(NOT ODELAB_SCENE_NAMES)
    message(FATAL_ERROR "${_list}: no scene listed")
  endif()
endmacro()

function(odelab_scene_definitions name out)
  set(${out} "ODELAB_SCENE_NAME=${name}" "ODELAB_SCENE_TITLE=\"${ODELAB_SCENE_TITLE_${name}}\"" PARENT_SCOPE)
endfunction()

function(odelab_write_scene_list file)
  set(json "[]")
  set(index 0)
  foreach(name IN LISTS ODELAB_SCENE_NAMES)
    string(JSON json SET "${json}" ${index} "{}")
    string(JSON json SET "${json}" ${index} name "\"${name}\"")
    # (the list's rule keeps quotes and backslashes out of a title: a JSON string as it stands)
    string(JSON json SET "${json}" ${index} title "\"${ODELAB_SCENE_TITLE_${name}}\"")
    math(EXPR index "${index} + 1")
  endforeach()
  file(WRITE "${file}.tmp" "${json}\n")
  file(RENAME "${file}.tmp" "${file}")
endfunction()
