/* batch_files_test.c — tools/batch/batch_files.c: the files of a job line
 * from its command's option table (outputs: --output/-o, --report,
 * --heatmap, --save-job; inputs: positional words and text options naming
 * an existing file), its own --threads and --max-memory, the defects, and
 * paths made absolute. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "batch/batch_files.h"
#include "capi/check.h"
#include "tools/temp_folder.h"

/* The line classified last; its words are what `files` points into. */
static job_line line;

static int classify(const char* text, int check_inputs, batch_line_files* files, const char** error) {
    job_line_free(&line);
    const char* defect = NULL;
    if (job_tokenize(text, &line, &defect) != 0) return -2;
    return batch_line_files_of(&line, check_inputs, files, error);
}

int main(void) {
    char folder[4096], keep_out[4096], text[8192];
    CHECK(temp_folder_make(folder) == 0);
    CHECK(temp_write(temp_path(keep_out, folder, "keep.json"), "{}") == 0);

    batch_line_files files;
    const char* error = NULL;
    snprintf(text, sizeof text,
             "drain in.stl -o out.stl --report=r.json --heatmap h.ply --keep-out %s --threads 2 --max-memory 1G",
             keep_out);
    CHECK(classify(text, 1, &files, &error) == 0);
    CHECK(files.output_count == 3 && strcmp(files.outputs[0], "out.stl") == 0 &&
          strcmp(files.outputs[1], "r.json") == 0 && strcmp(files.outputs[2], "h.ply") == 0);
    CHECK(files.input_count == 2 && strcmp(files.inputs[0], "in.stl") == 0 && strcmp(files.inputs[1], keep_out) == 0);
    CHECK(files.output && strcmp(files.output, "out.stl") == 0 && files.report && strcmp(files.report, "r.json") == 0);
    CHECK(files.threads && strcmp(files.threads, "2") == 0 && files.max_memory && strcmp(files.max_memory, "1G") == 0);

    /* A text option that names no file is an input only when not checked. */
    CHECK(classify("mold in.stl -o out --decomposition missing.json", 1, &files, &error) == 0);
    CHECK(files.input_count == 1);
    CHECK(classify("mold in.stl -o out --decomposition missing.json", 0, &files, &error) == 0);
    CHECK(files.input_count == 2 && strcmp(files.inputs[1], "missing.json") == 0);
    /* After --, every word is positional; a negative number is a value. */
    CHECK(classify("info -- -strange-name.stl", 0, &files, &error) == 0);
    CHECK(files.input_count == 1 && strcmp(files.inputs[0], "-strange-name.stl") == 0);

    CHECK(classify("nosuch in.stl", 0, &files, &error) == -1 && strcmp(error, "no such command") == 0);
    CHECK(classify("hollow in.stl --wal 3mm", 0, &files, &error) == -1 &&
          strcmp(error, "an option the command does not have") == 0);
    CHECK(classify("hollow in.stl -o", 0, &files, &error) == -1 && strcmp(error, "an option without its value") == 0);

    char* absolute = batch_files_absolute("/work/here", "a/b.stl");
    CHECK(absolute && strcmp(absolute, "/work/here/a/b.stl") == 0);
    free(absolute);
    absolute = batch_files_absolute("/work/here", "/elsewhere/b.stl");
    CHECK(absolute && strcmp(absolute, "/elsewhere/b.stl") == 0);
    free(absolute);
    char* names[] = {"b", "B", "a", "a0"};
    batch_files_sort(names, 4);
    CHECK(strcmp(names[0], "B") == 0 && strcmp(names[1], "a") == 0 && strcmp(names[2], "a0") == 0 &&
          strcmp(names[3], "b") == 0);
    job_line_free(&line);
    temp_folder_remove(folder);
    return check_summary();
}
