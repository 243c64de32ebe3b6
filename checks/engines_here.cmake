# ---- the engines the checks run on, decided once as the build decides -------------
# (peers/engines/CMakeLists.txt): Bullet and MuJoCo where their libraries
# were found; Havok, Jolt and Rapier where Node.js is and `npm ci` has run in
# peers/wasm. ODELAB_CHECK_ENGINES lists those here; ODELAB_CHECK_ENGINES_SKIPPED
# those missing, which a check names as skipped.
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
if(ODELAB_ENGINE_NODE AND EXISTS ${CMAKE_SOURCE_DIR}/peers/wasm/node_modules/.package-lock.json)
  list(APPEND ODELAB_CHECK_ENGINES havok jolt rapier)
else()
  list(APPEND ODELAB_CHECK_ENGINES_SKIPPED havok jolt rapier)
endif()
