# Checks that every RUNPATH (or RPATH) entry of the ELF files in PREFIX's
# bin/ and lib/ (the Python extension modules included) is relative to
# $ORIGIN and resolves to a folder inside PREFIX: a moved prefix must not
# search outside itself. The Python modules' $ORIGIN/../../../../lib, once set
# for every target, sent the program's and the OSMesa library's search
# outside the prefix. Fails with "FAILED: ... outside the prefix".
# Included by RunConsumer.cmake, or: cmake -DPREFIX=... -P CheckRunpaths.cmake
if (NOT DEFINED PREFIX)
  message(FATAL_ERROR "CheckRunpaths.cmake needs -DPREFIX=...")
endif ()
# Compared as an absolute, normal path (a trailing slash or ../ in it would
# make every entry look outside).
get_filename_component(PREFIX "${PREFIX}" ABSOLUTE)
find_program(readelf_program readelf)
if (readelf_program)
  file(GLOB_RECURSE elf_candidates LIST_DIRECTORIES false "${PREFIX}/bin/*" "${PREFIX}/lib/*.so*")
  set(checked 0)
  foreach (binary IN LISTS elf_candidates)
    if (IS_SYMLINK "${binary}")
      continue ()
    endif ()
    execute_process(COMMAND "${readelf_program}" -d "${binary}"
      RESULT_VARIABLE code OUTPUT_VARIABLE dynamic ERROR_QUIET)
    if (NOT code EQUAL 0)
      continue () # not an ELF file
    endif ()
    math(EXPR checked "${checked} + 1")
    # " 0x...1d (RUNPATH)  Library runpath: [$ORIGIN/../lib]"
    string(REGEX MATCHALL "Library r[a-z]*path: \\[[^\n]*\\]" entries "${dynamic}")
    foreach (entry IN LISTS entries)
      string(REGEX REPLACE "^Library r[a-z]*path: \\[(.*)\\]$" "\\1" search_path "${entry}")
      get_filename_component(origin "${binary}" DIRECTORY)
      string(REPLACE ":" ";" folders "${search_path}")
      foreach (folder IN LISTS folders)
        string(REPLACE "\${ORIGIN}" "$ORIGIN" folder "${folder}")
        if (NOT folder MATCHES "^\\$ORIGIN(/|$)")
          message(FATAL_ERROR "FAILED: ${binary}: RUNPATH entry '${folder}' is not relative to $ORIGIN")
        endif ()
        string(REPLACE "$ORIGIN" "${origin}" resolved "${folder}")
        get_filename_component(resolved "${resolved}" ABSOLUTE)
        string(FIND "${resolved}/" "${PREFIX}/" at)
        if (NOT at EQUAL 0)
          message(FATAL_ERROR "FAILED: ${binary}: RUNPATH entry '${folder}' is ${resolved}, outside the prefix ${PREFIX}")
        endif ()
      endforeach ()
    endforeach ()
  endforeach ()
  if (checked EQUAL 0)
    message(FATAL_ERROR "FAILED: readelf read no installed program or library")
  endif ()
  message(STATUS "RUNPATH: ${checked} installed ELF files, every entry inside the prefix")
else ()
  message(STATUS "no readelf: the installed RUNPATHs are not checked")
endif ()
