/* batch_summary.h — what a state folder says about its batch: for every task
 * of its plan, done, failed (with the exit code and message of its record, or
 * the reason Slurm gives for an array task that ended without writing one:
 * time limit, memory, cancelled) or pending. Written as STATE/status.json
 * (`--status`) or, with each command's key figures read from its --report
 * (its top-level numbers and flags, and the length of each top-level list,
 * e.g. material_saved_fraction, holes, predicted_residual_fraction), as the
 * batch report (`--report`). Reads every record once; asks Slurm (scontrol,
 * then the job-completion log) only about tasks without one. */
#ifndef FABVDB_BATCH_SUMMARY_H
#define FABVDB_BATCH_SUMMARY_H

typedef struct batch_counts {
    int tasks, done, failed, pending;
    int first_failure; /* the exit code of the first failed task in plan order, or 0 */
} batch_counts;

/* Reads the state folder. With print, prints the summary on stdout (each
 * failure with its message, then the pending tasks). Writes the status to
 * STATE/status.json and, with report_path, the report there. Returns 0, or an
 * exit code after printing the error (2: not a state folder). */
int batch_summary(const char* state, int print, const char* report_path, batch_counts* counts);

#endif
