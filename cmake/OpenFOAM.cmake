# OpenFOAM v1912 as Debian ships it: libraries in /usr/lib, no headers.
# etc/setup unpacks Debian's source package into SPOUTLAB_CACHE and builds the
# lnInclude directories; this file turns that into an imported target.
set(SPOUTLAB_CACHE "$ENV{SPOUTLAB_CACHE}" CACHE PATH "Cache with the OpenFOAM source tree")
if(NOT SPOUTLAB_CACHE)
  set(SPOUTLAB_CACHE "$ENV{HOME}/.cache/spoutlab")
endif()
set(OPENFOAM_SRC "${SPOUTLAB_CACHE}/openfoam/src")
if(NOT EXISTS "${OPENFOAM_SRC}/OpenFOAM/lnInclude/fvCFD.H" AND
   NOT EXISTS "${OPENFOAM_SRC}/finiteVolume/lnInclude/fvCFD.H")
  message(FATAL_ERROR "OpenFOAM headers not found under ${OPENFOAM_SRC}: run etc/setup first")
endif()

add_library(OpenFOAM::finiteVolume INTERFACE IMPORTED)
target_include_directories(OpenFOAM::finiteVolume SYSTEM INTERFACE
  ${OPENFOAM_SRC}/finiteVolume/lnInclude
  ${OPENFOAM_SRC}/meshTools/lnInclude
  ${OPENFOAM_SRC}/OpenFOAM/lnInclude
  ${OPENFOAM_SRC}/OSspecific/POSIX/lnInclude)
target_compile_definitions(OpenFOAM::finiteVolume INTERFACE
  OPENFOAM=1912 WM_DP WM_LABEL_SIZE=32 NoRepository)
target_compile_options(OpenFOAM::finiteVolume INTERFACE
  -m64 -ftemplate-depth-100 -Wno-old-style-cast -Wno-unused-parameter)
target_link_options(OpenFOAM::finiteVolume INTERFACE
  "LINKER:--add-needed,--no-as-needed")
target_link_libraries(OpenFOAM::finiteVolume INTERFACE
  /usr/lib/libfiniteVolume.so /usr/lib/libmeshTools.so /usr/lib/libOpenFOAM.so dl m)
