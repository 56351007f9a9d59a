# pack_addon.cmake — cmake -P script: stages the add-on, the built fabvdb
# package and a stripped copy of libfabvdb (under its soname, found through
# the extension's $ORIGIN run path) and zips them as fabvdb_blender/...
# Inputs: STAGE, ZIP, ADDON, PACKAGE, LIBRARY, SONAME, STRIP (may be empty).
file(REMOVE_RECURSE "${STAGE}")
set(root "${STAGE}/fabvdb_blender")
file(GLOB addon "${ADDON}/*.py")
file(COPY ${addon} DESTINATION "${root}")
file(GLOB package "${PACKAGE}/*.py" "${PACKAGE}/*.pyi" "${PACKAGE}/py.typed" "${PACKAGE}/_fabvdb*.so")
file(COPY ${package} DESTINATION "${root}/vendor/fabvdb")
file(COPY_FILE "${LIBRARY}" "${root}/vendor/fabvdb/${SONAME}")
if(STRIP)
  execute_process(COMMAND "${STRIP}" --strip-unneeded "${root}/vendor/fabvdb/${SONAME}")
endif()
file(REMOVE "${ZIP}")
execute_process(COMMAND "${CMAKE_COMMAND}" -E tar cf "${ZIP}" --format=zip fabvdb_blender
                WORKING_DIRECTORY "${STAGE}" RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "could not write ${ZIP}")
endif()
