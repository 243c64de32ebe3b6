# ---- the scenes in the browser (doc/web.md; label web) -------------------------
# Each scene runs in headless Chromium from build-web/site (scripts/odelab.sh
# web builds it; scripts/odelab.sh test does before these run): in a window
# it must draw a picture with a shadow cast on a lit surface (as the desktop's
# screenshot check asks), and headless its metric must match the desktop
# build's headless run with the same options. Without the site the checks
# are skipped, saying why (scripts/web/check-scene.sh).
#
# Tolerances: WebAssembly does IEEE double arithmetic as the desktop does,
# but Emscripten's maths library (musl's) and glibc's differ in the last
# bits of sin, cos, exp, pow and atan2, and libc++'s random distributions
# are not libstdc++'s; ODE's QuickStep carries those bits into every body.
# A metric that counts outcomes (bodies at rest, dominoes down, cubes
# stopped) is compared exactly: the last bits must not change what happened.
# A measured quantity is allowed the difference stated beside it, a small
# fraction of the bound the scene's own check (checks/programs/) asserts.
set(ODELAB_WEB_SITE ${CMAKE_SOURCE_DIR}/build-web/site CACHE PATH "the browser build's site (scripts/odelab.sh web)")

# The checks need Chromium and Node to run, and Emscripten to build the site
# (unless it is built already): where one is missing they are left out, said
# once here (Node once, by peers/engines/CMakeLists.txt, where the engine adapters are built).
find_program(ODELAB_NODE NAMES node nodejs)
find_program(ODELAB_CHROMIUM NAMES chromium chromium-browser)
find_program(ODELAB_EMCC emcc)
set(_web_missing)
if(NOT ODELAB_CHROMIUM)
  message(STATUS "Browser checks left out (label web): chromium not found; Debian's chromium brings it")
  list(APPEND _web_missing chromium)
endif()
if(NOT ODELAB_EMCC AND NOT EXISTS ${ODELAB_WEB_SITE})
  message(STATUS "Browser checks left out (label web): emcc not found and no site built; "
                 "Debian's emscripten brings it")
  list(APPEND _web_missing emcc)
endif()
if(NOT ODELAB_NODE)
  if(NOT ODELAB_BUILD_PEERS)
    message(STATUS "Browser checks left out (label web): node not found; Debian's nodejs brings it")
  endif()
  list(APPEND _web_missing node)
endif()

if(_web_missing)
  return()
endif()

# Each scene's run in the browser, as its checks file
# (checks/programs/<scene>.cmake) asked with odelab_web_check
# (check_functions.cmake): the metric, its tolerance, the length, options.
function(odelab_register_web_check scene metric tolerance)
  cmake_parse_arguments(W "" "SECONDS;DOWNLOAD" "ARGS" ${ARGN})
  set(extra)
  if(W_SECONDS)
    list(APPEND extra --seconds ${W_SECONDS})
  endif()
  if(W_DOWNLOAD)
    list(APPEND extra --download ${W_DOWNLOAD})
  endif()
  add_test(NAME web_${scene}
    COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/web/check-scene.sh --site ${ODELAB_WEB_SITE}
            --native $<TARGET_FILE:${scene}> --out ${CMAKE_CURRENT_BINARY_DIR}/web_${scene}
            --metric ${metric} --tolerance ${tolerance} --shadow-check $<TARGET_FILE:screenshot_check>
            ${extra} -- ${W_ARGS})
  set_tests_properties(web_${scene} PROPERTIES LABELS web SKIP_RETURN_CODE 77 TIMEOUT 600 PROCESSORS 2)
endfunction()

# Each scene's run (checks/programs/<scene>.cmake) gives the metric, its
# tolerance (absolute, in the metric's unit), the headless length and the
# options. Measured on this project's machine, every metric came out
# identical in both builds to the ten significant digits the metrics file
# keeps (doc/web.md); the tolerances leave room for last-bit differences on
# another machine and stay far inside each scene's own bound. Counts are
# compared exactly.

get_property(_web_scenes GLOBAL PROPERTY ODELAB_WEB_CHECK_SCENES)
foreach(_scene IN LISTS _web_scenes)
  get_property(_arguments GLOBAL PROPERTY ODELAB_WEB_CHECK_${_scene})
  odelab_register_web_check(${_scene} ${_arguments})
endforeach()

# The page itself: a coarse clock (two frames at one time) does not stop a
# run, a refused address parameter is named without command-line advice,
# and the pages load no missing file and have their icon
# (scripts/web/check-page.sh says what each asks).
foreach(what clock bad-option files)
  string(REPLACE "-" "_" name web_page_${what})
  add_test(NAME ${name}
    COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/web/check-page.sh --site ${ODELAB_WEB_SITE}
            --out ${CMAKE_CURRENT_BINARY_DIR}/${name} ${what})
  set_tests_properties(${name} PROPERTIES LABELS web SKIP_RETURN_CODE 77 TIMEOUT 600 PROCESSORS 2)
endforeach()

# The compare view in the page: test2 and test9 on ODE, Havok, Jolt, Rapier
# and PhysX in one canvas, each view showing the bodies, and every engine's
# figures against the desktop's --engine run of the same options, within
# the tolerance the scene's own browser check states (above)
# (scripts/web/check_compare.py). The picture is taken where the engines
# agree on the bodies' places: test2's pendulum after 3 s, test9's ball at
# 0.3 s, falling, before its first bounce (0.48 s; each engine bounces its
# own way after it). The desktop's runs of the web engines need Node.js
# (peers/engines/CMakeLists.txt).
set(_window_seconds_test2 3)
set(_window_seconds_test9 0.3)
if(ODELAB_ENGINE_NODE)
  foreach(_scene test2 test9)
    get_property(_arguments GLOBAL PROPERTY ODELAB_WEB_CHECK_${_scene})
    cmake_parse_arguments(W "" "SECONDS;DOWNLOAD" "ARGS" ${_arguments})
    list(GET _arguments 0 _metric)
    list(GET _arguments 1 _tolerance)
    set(_length)
    if(W_SECONDS)
      set(_length --seconds ${W_SECONDS})
    endif()
    add_test(NAME web_compare_${_scene}
      COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/web/check_compare.py --site ${ODELAB_WEB_SITE}
              --native $<TARGET_FILE:${_scene}> --out ${CMAKE_CURRENT_BINARY_DIR}/web_compare_${_scene}
              --engines havok,jolt,rapier,physx --metric ${_metric} --tolerance ${_tolerance}
              --view-bodies $<TARGET_FILE:view_bodies> --window-seconds ${_window_seconds_${_scene}} ${_length}
              -- ${W_ARGS})
    set_tests_properties(web_compare_${_scene} PROPERTIES LABELS "web;compare" SKIP_RETURN_CODE 77 TIMEOUT 900
                         PROCESSORS 2)
  endforeach()
endif()
