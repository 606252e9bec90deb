# Warnings as an INTERFACE target, never as global flags (house style 7.7).
# GCC 12 reports members left out of a designated initialiser even when they
# have defaults; options structs set with designated initialisers are the
# house style, so that one warning is off.
add_library(lsolid_warnings INTERFACE)
add_library(lsolid::warnings ALIAS lsolid_warnings)
target_compile_options(lsolid_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow
                                                 -Wno-missing-field-initializers
                                                 $<$<BOOL:${LSOLID_WERROR}>:-Werror>)

# Every target that takes the warnings takes the sanitizer settings too
# (cmake/LsolidSanitizers.cmake), so one switch covers the whole project.
include(${CMAKE_CURRENT_LIST_DIR}/LsolidSanitizers.cmake)
target_link_libraries(lsolid_warnings INTERFACE lsolid_sanitizers)
