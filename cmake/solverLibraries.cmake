# solverLibraries.cmake — optional libraries of the sparse solve (docs/solvers.md)
#
#   -DAMPLE_MUMPS=ON        MUMPS, its sequential library (apt-get install libmumps-seq-dev;
#                           libopenblas0-serial makes its dense fronts fast): solver=MUMPS
#   -DAMPLE_PETSC=ON        PETSc with Open MPI (apt-get install petsc-dev): solver=PETSC,
#                           MUMPS over the ranks of `mpirun -n N ample ...`; not with
#                           AMPLE_MUMPS (its sequential library's MPI stand-ins clash)
#
# Both OFF by default: the default build uses Eigen only. Each ON option defines
# AMPLE_HAVE_MUMPS / AMPLE_HAVE_PETSC on amplecore (and so on every program
# linked to it); a library that is asked for and not found stops the configure.
option(AMPLE_MUMPS "MUMPS (sequential) for the sparse solve (solver=MUMPS)" OFF)
option(AMPLE_PETSC "PETSc over MPI ranks for the sparse solve (solver=PETSC)" OFF)

# amplecore (and every program linked to it) gets the headers, the libraries and the define
function(ample_use_library define include_dir libraries)
  target_include_directories(amplecore PUBLIC ${include_dir})
  target_link_libraries(amplecore PUBLIC ${libraries})
  target_compile_definitions(amplecore PUBLIC ${define})
  message(STATUS "${define}: ${libraries}")
endfunction()

# the header and the libraries of an option: FATAL_ERROR naming the Debian package if one is missing;
# then ample_use_library (define, the header's folder, the libraries in the order given)
function(ample_find_library option define header suffix package)
  find_path(${define}_INCLUDE_DIR ${header} PATH_SUFFIXES ${suffix})
  if(NOT ${define}_INCLUDE_DIR)
    message(FATAL_ERROR "${option}=ON: ${header} not found (Debian: apt-get install ${package})")
  endif()
  set(libraries "")
  foreach(lib ${ARGN})
    find_library(${define}_${lib}_LIBRARY ${lib})
    if(NOT ${define}_${lib}_LIBRARY)
      message(FATAL_ERROR "${option}=ON: lib${lib} not found (Debian: apt-get install ${package})")
    endif()
    list(APPEND libraries ${${define}_${lib}_LIBRARY})
  endforeach()
  ample_use_library(${define} "${${define}_INCLUDE_DIR}" "${libraries}")
endfunction()

if(AMPLE_MUMPS)
  ample_find_library(AMPLE_MUMPS AMPLE_HAVE_MUMPS dmumps_c.h "" libmumps-seq-dev
                     dmumps_seq mumps_common_seq mpiseq_seq pord_seq)
endif()

if(AMPLE_PETSC)
  if(AMPLE_MUMPS)   # the sequential MUMPS brings its own stand-ins for MPI's Fortran calls
    message(FATAL_ERROR "AMPLE_PETSC=ON and AMPLE_MUMPS=ON in one build: the sequential MUMPS library "
                        "defines MPI stand-ins that break PETSc's MPI; build them apart (presets fast, mpi)")
  endif()
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(PETSC PETSc)
  set(MPI_CXX_SKIP_MPICXX ON)
  find_package(MPI COMPONENTS CXX)
  if(NOT PETSC_FOUND OR NOT MPI_CXX_FOUND)
    message(FATAL_ERROR "AMPLE_PETSC=ON: PETSc (pkg-config PETSc) or MPI not found (Debian: apt-get install petsc-dev)")
  endif()
  find_library(PETSC_LIBRARY NAMES ${PETSC_LIBRARIES} HINTS ${PETSC_LIBRARY_DIRS})
  ample_use_library(AMPLE_HAVE_PETSC "${PETSC_INCLUDE_DIRS};${MPI_CXX_INCLUDE_DIRS}" "${PETSC_LIBRARY};${MPI_CXX_LIBRARIES}")
endif()
