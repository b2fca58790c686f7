# LIGGGHTS 3.8.0 from Debian (libliggghts-dev): C++ headers and one shared library.
find_path(LIGGGHTS_INCLUDE_DIR lammps.h PATHS /usr/include/liggghts REQUIRED)
find_library(LIGGGHTS_LIBRARY liggghts REQUIRED)
add_library(LIGGGHTS::liggghts INTERFACE IMPORTED)
target_include_directories(LIGGGHTS::liggghts SYSTEM INTERFACE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(LIGGGHTS::liggghts INTERFACE ${LIGGGHTS_LIBRARY} MPI::MPI_CXX)
