/* orientation_file.c — reads `--orientations` files (see orientation_file.h). */
#include "orientation_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/status_text.h"

int cli_read_orientations(const cli_run* run, const char* spec, double** values, size_t* count) {
    *values = NULL;
    *count = 0;
    if (!spec || strcmp(spec, "all") == 0) return CLI_EXIT_OK;
    FILE* file = fopen(spec, "r");
    if (!file) {
        status_print(run->command->name, FABVDB_ERR_IO, "%s: cannot open the orientations file", spec);
        return cli_exit_code(FABVDB_ERR_IO);
    }
    char line[512];
    size_t capacity = 0, line_number = 0;
    double* list = NULL;
    while (fgets(line, sizeof line, file)) {
        ++line_number;
        char* hash = strchr(line, '#');
        if (hash) *hash = '\0';
        double x, y, z;
        char extra;
        const int fields = sscanf(line, "%lf %lf %lf %c", &x, &y, &z, &extra);
        if (fields <= 0) continue; /* blank or comment */
        if (fields != 3 || !(sqrt(x * x + y * y + z * z) > 0.0)) {
            status_print(run->command->name, FABVDB_ERR_BAD_INPUT, "%s:%zu: expected a direction \"x y z\"", spec,
                         line_number);
            free(list);
            fclose(file);
            return CLI_EXIT_BAD_INPUT;
        }
        if (*count == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            double* grown = realloc(list, 3 * capacity * sizeof(double));
            if (!grown) {
                free(list);
                fclose(file);
                fprintf(stderr, "fabvdb %s: out of memory\n", run->command->name);
                return CLI_EXIT_INTERNAL;
            }
            list = grown;
        }
        list[3 * *count] = x;
        list[3 * *count + 1] = y;
        list[3 * *count + 2] = z;
        ++*count;
    }
    fclose(file);
    if (*count == 0) {
        status_print(run->command->name, FABVDB_ERR_BAD_INPUT, "%s: no orientation in the file", spec);
        free(list);
        return CLI_EXIT_BAD_INPUT;
    }
    *values = list;
    return CLI_EXIT_OK;
}
