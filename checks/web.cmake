# ---- the scenes in the browser (doc/web.md; label web) -------------------------
# Each scene runs in headless Chromium from build-web/site (scripts/odelab.sh
# web builds it; scripts/odelab.sh test does before these run): in a window
# it must draw a picture, and headless its metric must match the desktop
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

# odelab_web_check(SCENE METRIC TOLERANCE [DOWNLOAD FILE] ARGS ...)
function(odelab_web_check scene metric tolerance)
  cmake_parse_arguments(W "" "DOWNLOAD" "ARGS" ${ARGN})
  set(extra)
  if(W_DOWNLOAD)
    set(extra --download ${W_DOWNLOAD})
  endif()
  add_test(NAME web_${scene}
    COMMAND bash ${CMAKE_SOURCE_DIR}/scripts/web/check-scene.sh --site ${ODELAB_WEB_SITE}
            --native $<TARGET_FILE:${scene}> --out ${CMAKE_CURRENT_BINARY_DIR}/web_${scene}
            --metric ${metric} --tolerance ${tolerance} ${extra} -- ${W_ARGS})
  set_tests_properties(web_${scene} PROPERTIES LABELS web SKIP_RETURN_CODE 77 TIMEOUT 600 PROCESSORS 2)
endfunction()
