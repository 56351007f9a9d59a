/* batch_plan.h — the tasks of a batch, read from a job file (tools/common/job.h):
 *
 *  - explicit lines: without 'task' lines the whole file is one task; with
 *    them, each 'task NAME' line starts a task made of the lines below it;
 *  - a recipe: lines with placeholders, applied to every file of --inputs
 *    (a glob pattern, braces allowed, or a folder of meshes); one input is one
 *    task named after its stem, whose outputs go to its own folder OUT/STEM.
 *
 * Placeholders: {input} the input's absolute path, {name} its file name,
 * {stem} its name without the extension, {out} the task's output folder,
 * {prev} the --output of the line above; {{ and }} stand for braces.
 * A task's lines run in order in the directory the job's last 'directory'
 * line named (relative ones resolve from the one before; default: where
 * batch runs). The plan is written into the state folder as an explicit job
 * file, so every Slurm array task reads the same tasks (`--task`); its
 * 'line N' lines keep each command's line number in the job it came from. */
#ifndef FABVDB_BATCH_PLAN_H
#define FABVDB_BATCH_PLAN_H

#include <stddef.h>

#include "common/job.h"

typedef struct batch_plan_line {
    job_line line;    /* the command and its arguments, placeholders replaced */
    int source_line;  /* its line number in the job file */
    char* directory;  /* absolute; where the line runs */
} batch_plan_line;

typedef struct batch_task {
    char* name;  /* unique in the plan; letters, digits and . _ - + only */
    char* input; /* the recipe's input (absolute), or NULL */
    char* out;   /* the task's output folder (absolute), or NULL */
    batch_plan_line* lines;
    int line_count;
} batch_task;

typedef struct batch_plan {
    batch_task* tasks;
    int task_count;
    int recipe; /* the job used placeholders of an input */
} batch_plan;

/* Reads the job at job_path; `inputs` (pattern or folder) and `out` (folder,
 * created if missing) are the recipe's, or NULL. Returns 0, or an exit code
 * (1 usage: a recipe without --inputs or --out, inputs without a recipe;
 * 2 bad input: the job file's defect, naming its line, or no input matches)
 * with the message (without "fabvdb batch: ") in error. */
int batch_plan_read(const char* job_path, const char* inputs, const char* out, batch_plan* plan, char* error,
                    size_t error_size);
/* Writes the plan as an explicit job file, atomically. Returns 0 or -1. */
int batch_plan_write(const batch_plan* plan, const char* source, const char* path);
void batch_plan_free(batch_plan* plan);
/* The index of the task called `name`, or -1. */
int batch_plan_find(const batch_plan* plan, const char* name);

#endif
