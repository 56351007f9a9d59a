# write_man_page.cmake — writes the man page fabvdb.1 at build time from the
# option tables, by running `fabvdb help --man` (tools/cli/reference.c).
# Usage: cmake -DFABVDB=path/to/fabvdb -DOUTPUT=path/to/fabvdb.1 -P write_man_page.cmake
# The page appears whole or not at all (temporary file, then rename).
execute_process(COMMAND "${FABVDB}" help --man OUTPUT_FILE "${OUTPUT}.tmp" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(REMOVE "${OUTPUT}.tmp")
  message(FATAL_ERROR "'${FABVDB} help --man' failed: ${result}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
