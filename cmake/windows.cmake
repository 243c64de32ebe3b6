# What the Windows build (MinGW-w64, cross or under MSYS2) does differently;
# included by CMakeLists.txt after the libraries are found.

# Console programs: SDL's pkg-config asks for -mwindows, a GUI program, whose
# standard output and error go nowhere; the programs report there. It also
# renames main to SDL_main (-Dmain=SDL_main) for its WinMain to call, which
# a console program does not need, and which gives a C++ SDL_main where no
# SDL_main.h declares it: each program's own main is kept.
foreach(_target PkgConfig::SDL2 PkgConfig::SDL2_TTF PkgConfig::IMGUI)
  foreach(_property INTERFACE_LINK_OPTIONS INTERFACE_LINK_LIBRARIES INTERFACE_COMPILE_OPTIONS
                    INTERFACE_COMPILE_DEFINITIONS)
    get_target_property(_flags ${_target} ${_property})
    if(_flags)
      list(REMOVE_ITEM _flags -mwindows -Dmain=SDL_main main=SDL_main)
      set_target_properties(${_target} PROPERTIES ${_property} "${_flags}")
    endif()
  endforeach()
endforeach()
add_link_options(-mconsole)
# One .exe with nothing beside it to install: the C++ runtime and
# winpthreads linked in, as the libraries are.
if(CMAKE_CROSSCOMPILING)
  add_link_options(-static)
endif()

# Windows has no DejaVu Sans Mono in a known place: the build machine's copy,
# where there is one, goes beside the programs (the font search's third place).
set(ODELAB_WINDOWS_FONT /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf CACHE FILEPATH
    "The HUD font copied beside the Windows programs (empty: none)")
if(ODELAB_WINDOWS_FONT AND EXISTS "${ODELAB_WINDOWS_FONT}")
  add_custom_target(odelab_windows_font ALL
    COMMAND ${CMAKE_COMMAND} -E copy ${ODELAB_WINDOWS_FONT} ${CMAKE_BINARY_DIR}/tests/fonts/DejaVuSansMono.ttf
    COMMENT "Copying the HUD font next to the Windows programs")
endif()
