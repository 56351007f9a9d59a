/* batch_slurm.h — a batch on a Slurm cluster. The tasks go out as one job
 * array (`sbatch --parsable --array=0-(M-1)%K`); array index i runs the tasks
 * on line i+1 of STATE/slurm/submit-N.tasks (one task per index, or chunks
 * when there are more tasks than the cluster's MaxArraySize allows) as
 * `fabvdb batch STATE/plan.job --state STATE --task NAMES`, each task writing
 * its own record into the state folder on the shared filesystem. Every
 * submitted task is listed in STATE/slurm/submissions.tsv (job, index, task),
 * so a task that Slurm ended without a record (time limit, memory, scancel,
 * node failure) is explained by `scontrol show job`, or, once Slurm has
 * forgotten the job, by the job-completion log (jobcomp/filetxt) whose path
 * the submission noted. `--wait` polls squeue each second, not
 * `sbatch --wait`, whose polling backs off to 32 s. */
#ifndef FABVDB_BATCH_SLURM_H
#define FABVDB_BATCH_SLURM_H

#include <stddef.h>

#include "batch_plan.h"

typedef struct batch_slurm_options {
    const char* partition;  /* or NULL */
    int max_running;        /* array tasks at once (%K), 0: no limit */
    const char* time;       /* Slurm's time format (minutes, MM:SS, HH:MM:SS, D-HH), or NULL */
    double mem;             /* bytes per array task, 0: the cluster's default */
    int wait;               /* the caller waits (batch_slurm_wait) */
    int quiet;
    const char* state;      /* absolute */
} batch_slurm_options;

/* Submits the tasks todo[0..todo_count) of the plan written at
 * STATE/plan.job, in four phases: Slurm's configuration (scontrol), the
 * submission's files, sbatch, the note in submissions.tsv. Removes their old
 * records first. Returns 0 with the array's job id in `job` (empty when there
 * was nothing to submit), or an exit code after printing the error (sbatch's
 * message when it refuses). */
int batch_slurm_submit(const batch_plan* plan, const int* todo, int todo_count, const batch_slurm_options* options,
                       char* job, size_t job_size);
/* Waits until squeue lists none of the tasks of array `job` (options->wait),
 * showing how many are left on a terminal. Returns 0, or 130 when SIGINT or
 * SIGTERM (blocked by the caller) stops the wait, or an exit code after
 * printing squeue's error. */
int batch_slurm_wait(const char* job, const batch_slurm_options* options);

/* The submissions of a state folder, or NULL when it has none. */
typedef struct batch_slurm_jobs batch_slurm_jobs;
batch_slurm_jobs* batch_slurm_jobs_read(const char* state);
void batch_slurm_jobs_free(batch_slurm_jobs* jobs);
/* For a task without a record: 0 when it was never submitted or Slurm knows
 * nothing; 1 when its array task ended (reason: "Slurm job 12_3 TIMEOUT
 * (reason TimeLimit)"), 2 when it is still queued or running. Sets job to
 * "ARRAYJOB_INDEX" when it was submitted. */
int batch_slurm_reason(batch_slurm_jobs* jobs, const char* task, char* job, size_t job_size, char* reason,
                       size_t reason_size);
/* The exit code a Slurm reason stands for: 3 for TIMEOUT and OUT_OF_MEMORY
 * (a resource limit), 130 for CANCELLED, 4 otherwise. */
int batch_slurm_exit_code(const char* reason);

#endif
