/* batch_record_test.c — tools/batch/batch_record.c: a record written whole
 * (through tools/common/atomic_file.h) with its files' hashes, read back by
 * the JSON reader; batch_record_current says why a record is not current
 * (none, failed, lines changed, an input changed, an output gone); times in
 * ISO 8601 UTC. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "batch/batch_record.h"
#include "capi/check.h"
#include "common/json.h"
#include "tools/temp_folder.h"

int main(void) {
    char folder[4096], input[4096], output[4096], path[4096];
    CHECK(temp_folder_make(folder) == 0);
    CHECK(temp_write(temp_path(input, folder, "in.stl"), "solid in") == 0);
    CHECK(temp_write(temp_path(output, folder, "out.stl"), "solid out") == 0);

    /* One task of one line: repair in.stl -o out.stl (as a plan holds it). */
    batch_task task;
    memset(&task, 0, sizeof task);
    task.name = "t";
    batch_plan_line line;
    memset(&line, 0, sizeof line);
    const char* error = NULL;
    CHECK(job_tokenize("repair in.stl -o out.stl", &line.line, &error) == 0);
    line.source_line = 3;
    line.directory = folder;
    task.lines = &line;
    task.line_count = 1;

    batch_line_result result;
    memset(&result, 0, sizeof result);
    result.ran = 1;
    result.started = 1e9;
    result.ended = 1e9 + 2.5;
    result.peak_kib = 1024;
    batch_record record;
    memset(&record, 0, sizeof record);
    record.task = &task;
    record.done = 1;
    record.failed_line = -1;
    record.started = 1e9;
    record.ended = 1e9 + 3;
    record.lines = &result;
    snprintf(record.message, sizeof record.message, "a \"quoted\" message");
    CHECK(batch_file_list_add(&record.inputs, input) == 0);
    CHECK(batch_file_list_add(&record.outputs, output) == 0);
    CHECK(batch_file_list_add(&record.outputs, output) == 0); /* once only */
    CHECK(record.outputs.count == 1 && batch_file_list_has(&record.outputs, output));
    CHECK(batch_file_list_add(&record.inputs, temp_path(path, folder, "missing")) == 0 && record.inputs.count == 1);

    char record_path[4096];
    batch_record_path(folder, "t", record_path, sizeof record_path);
    char tasks[4096];
    CHECK(mkdir(temp_path(tasks, folder, "tasks"), 0755) == 0);
    CHECK(batch_record_write(&record, record_path) == 0);
    CHECK(temp_count(tasks, ".partial-") == 0);
    json_value* written = json_read_file(record_path, &error);
    CHECK(written != NULL);
    CHECK(strcmp(json_get_string(written, "format", ""), BATCH_RECORD_FORMAT) == 0);
    CHECK(strcmp(json_get_string(written, "message", ""), "a \"quoted\" message") == 0);
    CHECK(strcmp(json_get_string(written, "started", ""), "2001-09-09T01:46:40.000Z") == 0);
    CHECK(json_get_number(written, "seconds", 0) == 3);
    CHECK(json_get_number(written, "peak_memory_bytes", 0) == 1024 * 1024);
    const json_value* inputs = json_get(written, "inputs");
    CHECK(inputs && inputs->count == 1 && strcmp(json_get_string(inputs->child, "path", ""), input) == 0);
    CHECK(inputs && strlen(json_get_string(inputs->child, "sha256", "")) == BATCH_SHA256_HEX_LENGTH);
    json_free(written);

    const char* why = NULL;
    CHECK(batch_record_current(record_path, &task, &why) == 1);
    /* The lines changed. */
    batch_plan_line other = line;
    job_line changed;
    CHECK(job_tokenize("repair in.stl -o other.stl", &changed, &error) == 0);
    other.line = changed;
    batch_task other_task = task;
    other_task.lines = &other;
    CHECK(batch_record_current(record_path, &other_task, &why) == 0 && strcmp(why, "its command lines changed") == 0);
    job_line_free(&changed);
    /* An input changed, then an output is gone. */
    CHECK(temp_write(input, "solid changed") == 0);
    CHECK(batch_record_current(record_path, &task, &why) == 0 && strcmp(why, "an input changed") == 0);
    CHECK(temp_write(input, "solid in") == 0);
    CHECK(batch_record_current(record_path, &task, &why) == 1);
    CHECK(unlink(output) == 0);
    CHECK(batch_record_current(record_path, &task, &why) == 0 && strcmp(why, "an output changed or is gone") == 0);
    /* A failed record, and none. */
    record.done = 0;
    CHECK(batch_record_write(&record, record_path) == 0);
    CHECK(batch_record_current(record_path, &task, &why) == 0 && strcmp(why, "failed") == 0);
    CHECK(unlink(record_path) == 0);
    CHECK(batch_record_current(record_path, &task, &why) == 0 && strcmp(why, "no record") == 0);

    char time_text[64];
    batch_format_time(0.25, time_text, sizeof time_text);
    CHECK(strcmp(time_text, "1970-01-01T00:00:00.250Z") == 0);
    CHECK(batch_now() > 1.7e9);

    batch_file_list_free(&record.inputs);
    batch_file_list_free(&record.outputs);
    job_line_free(&line.line);
    temp_folder_remove(folder);
    return check_summary();
}
