# solverLibraries.cmake — optional libraries of the sparse solve (docs/scaling.md, "The sparse solve")
#
#   -DAMPLE_METIS=ON        METIS nested-dissection ordering (apt-get install libmetis-dev):
#                           solver=LDLT_METIS (Eigen's MetisOrdering)
#   -DAMPLE_SUITESPARSE=ON  SuiteSparse (apt-get install libsuitesparse-dev):
#                           solver=CHOLMOD (supernodal LL^T) and solver=UMFPACK
#   -DAMPLE_MUMPS=ON        MUMPS, its sequential library (apt-get install libmumps-seq-dev;
#                           libopenblas0-serial makes its dense fronts fast): solver=MUMPS
#   -DAMPLE_PETSC=ON        PETSc with Open MPI (apt-get install petsc-dev): solver=PETSC,
#                           MUMPS over the ranks of `mpirun -n N ample ...`; not with
#                           AMPLE_MUMPS (its sequential library's MPI stand-ins clash)
#
# All OFF by default: the default build uses Eigen only. Each ON option defines
# AMPLE_HAVE_METIS / AMPLE_HAVE_SUITESPARSE on amplecore (and so on every program
# linked to it); a library that is asked for and not found stops the configure.
option(AMPLE_METIS "METIS ordering for the sparse solve (solver=LDLT_METIS)" OFF)
option(AMPLE_SUITESPARSE "SuiteSparse solvers for the sparse solve (solver=CHOLMOD, UMFPACK)" OFF)
option(AMPLE_MUMPS "MUMPS (sequential) for the sparse solve (solver=MUMPS)" OFF)
option(AMPLE_PETSC "PETSc over MPI ranks for the sparse solve (solver=PETSC)" OFF)

# amplecore (and every program linked to it) gets the headers, the libraries and the define
function(ample_use_library define include_dir libraries)
  target_include_directories(amplecore PUBLIC ${include_dir})
  target_link_libraries(amplecore PUBLIC ${libraries})
  target_compile_definitions(amplecore PUBLIC ${define})
  message(STATUS "${define}: ${libraries}")
endfunction()

if(AMPLE_METIS)
  find_path(METIS_INCLUDE_DIR metis.h)
  find_library(METIS_LIBRARY metis)
  if(NOT METIS_INCLUDE_DIR OR NOT METIS_LIBRARY)
    message(FATAL_ERROR "AMPLE_METIS=ON: metis.h or libmetis not found (Debian: apt-get install libmetis-dev)")
  endif()
  ample_use_library(AMPLE_HAVE_METIS "${METIS_INCLUDE_DIR}" "${METIS_LIBRARY}")
endif()

if(AMPLE_SUITESPARSE)
  find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  set(SUITESPARSE_LIBRARIES "")
  foreach(lib cholmod umfpack amd colamd suitesparseconfig)
    find_library(SUITESPARSE_${lib}_LIBRARY ${lib})
    if(NOT SUITESPARSE_${lib}_LIBRARY)
      message(FATAL_ERROR "AMPLE_SUITESPARSE=ON: lib${lib} not found (Debian: apt-get install libsuitesparse-dev)")
    endif()
    list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${lib}_LIBRARY})
  endforeach()
  if(NOT SUITESPARSE_INCLUDE_DIR)
    message(FATAL_ERROR "AMPLE_SUITESPARSE=ON: cholmod.h not found (Debian: apt-get install libsuitesparse-dev)")
  endif()
  ample_use_library(AMPLE_HAVE_SUITESPARSE "${SUITESPARSE_INCLUDE_DIR}" "${SUITESPARSE_LIBRARIES}")
endif()

if(AMPLE_MUMPS)
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
  set(MUMPS_LIBRARIES "")
  foreach(lib dmumps_seq mumps_common_seq mpiseq_seq pord_seq)
    find_library(MUMPS_${lib}_LIBRARY ${lib})
    if(NOT MUMPS_${lib}_LIBRARY)
      message(FATAL_ERROR "AMPLE_MUMPS=ON: lib${lib} not found (Debian: apt-get install libmumps-seq-dev)")
    endif()
    list(APPEND MUMPS_LIBRARIES ${MUMPS_${lib}_LIBRARY})
  endforeach()
  if(NOT MUMPS_INCLUDE_DIR)
    message(FATAL_ERROR "AMPLE_MUMPS=ON: dmumps_c.h not found (Debian: apt-get install libmumps-seq-dev)")
  endif()
  ample_use_library(AMPLE_HAVE_MUMPS "${MUMPS_INCLUDE_DIR}" "${MUMPS_LIBRARIES}")
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
