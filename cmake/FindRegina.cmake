# Finds Regina's engine (Debian: regina-normal-dev), which ships no pkg-config or CMake file.
# Defines Regina::Engine.
find_path(REGINA_INCLUDE_DIR regina-core.h PATH_SUFFIXES regina-normal)
find_library(REGINA_ENGINE_LIBRARY regina-engine PATHS /usr/lib /usr/lib/x86_64-linux-gnu)
find_library(GMP_LIBRARY gmp)
find_library(GMPXX_LIBRARY gmpxx)
find_package(LibXml2 QUIET)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Regina REQUIRED_VARS REGINA_INCLUDE_DIR REGINA_ENGINE_LIBRARY GMP_LIBRARY GMPXX_LIBRARY)
if(Regina_FOUND AND NOT TARGET Regina::Engine)
  add_library(Regina::Engine UNKNOWN IMPORTED)
  set_target_properties(Regina::Engine PROPERTIES
    IMPORTED_LOCATION ${REGINA_ENGINE_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES "${REGINA_INCLUDE_DIR}")
  # Regina's inline headers call GMP directly, so its users link GMP too.
  target_link_libraries(Regina::Engine INTERFACE ${GMPXX_LIBRARY} ${GMP_LIBRARY})
  if(LibXml2_FOUND)
    target_link_libraries(Regina::Engine INTERFACE LibXml2::LibXml2)
  endif()
endif()
