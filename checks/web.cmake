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
# once here (Node once, by peers/CMakeLists.txt, where the peers are built).
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

# odelab_web_check(SCENE METRIC TOLERANCE [SECONDS S] [DOWNLOAD FILE] [ARGS ...])
function(odelab_web_check scene metric tolerance)
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

# The runs: the metric, its tolerance (absolute, in the metric's unit), the
# headless length, the options. Measured on this project's machine, every
# metric below came out identical in both builds to the ten significant
# digits the metrics file keeps (doc/web.md); the tolerances leave room for
# last-bit differences on another machine and stay far inside each scene's
# own bound.
# Counts: exact.
odelab_web_check(test0 bodies_resting_on_platform 0 SECONDS 10
  ARGS --spawn-interval 0.5 --spawn-count 6 --spawn-shapes box)
odelab_web_check(test1 balls_bounced 0 SECONDS 15 ARGS --erp 0 --cfm 0)
# 1e-6 against the scene's 1% bound. The window run's output file comes
# through the page's download link whole.
odelab_web_check(test2 energy_rel_variation 1e-6 SECONDS 10 DOWNLOAD Test2_output.txt ARGS --erp 0.4 --cfm 0)
odelab_web_check(test3 fallen_fraction 0 SECONDS 20)
# 1e-4 degree against the scene's 2 degrees.
odelab_web_check(test4 max_tilt_degrees 1e-4 SECONDS 5 ARGS --big-mass 5000)
# 1 micrometre against the scene's 5 cm window on the stack's height.
odelab_web_check(test5 stack_height 1e-6 SECONDS 5 ARGS --plates 10 --spawn-interval 0.3 --cfm 0)
# The time the stick fell: one step (0.001 s) either way.
odelab_web_check(test6 seconds_upright 0.001 SECONDS 10)
# 1 micrometre against the scene's 2 cm.
odelab_web_check(test7 max_joint_error 1e-6 ARGS --max-angular-speed 10 --throws 1 --throw-interval 5)
# 1e-9 against the scene's 1e-4.
odelab_web_check(test8 max_relative_elongation 1e-9 SECONDS 10 ARGS --erp 0.4 --cfm 0)
# 1e-10 against the scene's 1e-4.
odelab_web_check(test9 apex_error_20 1e-10 ARGS --erp 0.2 --cfm 0)
odelab_web_check(test10 stopped 0 ARGS --velocity 200 --launches 5)

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
