# ---- the engines the checks run on, decided once as the build decides -------------
# (peers/engines/CMakeLists.txt): Bullet and MuJoCo where their libraries
# were found; each of the WebAssembly engines (peers/engines/WasmEngines.cpp,
# peers/wasm/engine_server.js) where Node.js is and `npm ci` has installed
# its package in peers/wasm. ODELAB_CHECK_ENGINES lists those here;
# ODELAB_CHECK_ENGINES_SKIPPED those missing, which a check names as skipped.
set(ODELAB_CHECK_ENGINES)
set(ODELAB_CHECK_ENGINES_SKIPPED)
if(ODELAB_ENGINE_BULLET)
  list(APPEND ODELAB_CHECK_ENGINES bullet)
else()
  list(APPEND ODELAB_CHECK_ENGINES_SKIPPED bullet)
endif()
if(ODELAB_ENGINE_MUJOCO)
  list(APPEND ODELAB_CHECK_ENGINES mujoco)
else()
  list(APPEND ODELAB_CHECK_ENGINES_SKIPPED mujoco)
endif()
# Each WebAssembly engine and its npm package, read from the one table of
# them (a row opens `{"name", "Title", "package",`), in --list-engines' order.
file(STRINGS ${CMAKE_SOURCE_DIR}/peers/engines/WasmEngines.cpp _wasm_rows
     REGEX "^ *\\{\"[a-z0-9]+\", \"[^\"]+\", \"[^\"]+\",")
if(NOT _wasm_rows)
  message(FATAL_ERROR "checks/engines_here.cmake: no engine rows read from peers/engines/WasmEngines.cpp")
endif()
foreach(_row IN LISTS _wasm_rows)
  string(REGEX REPLACE "^ *\\{\"([a-z0-9]+)\", \"[^\"]+\", \"([^\"]+)\",.*" "\\1;\\2" _pair "${_row}")
  list(GET _pair 0 _engine)
  list(GET _pair 1 _package)
  if(ODELAB_ENGINE_NODE AND EXISTS ${CMAKE_SOURCE_DIR}/peers/wasm/node_modules/${_package}/package.json)
    list(APPEND ODELAB_CHECK_ENGINES ${_engine})
  else()
    list(APPEND ODELAB_CHECK_ENGINES_SKIPPED ${_engine})
    # Without node the engines were named once already (peers/engines/CMakeLists.txt).
    if(ODELAB_ENGINE_NODE)
      message(STATUS "Engine ${_engine} left out of the checks: the npm package ${_package} is not installed; "
                     "`npm ci` in peers/wasm brings it")
    endif()
  endif()
endforeach()
