// Slurm for `sunglint compare --slurm` and `render --slurm` (docs/cluster.md): the work
// goes to a cluster as one job array (sbatch --array, one element per task, SLURM_ARRAY_TASK_ID
// naming it, %N capping how many run at once) and, for a study, a merge job that depends on
// it (afterok) and writes the report. Slurm does the scheduling; sunglint only writes the
// batch scripts, submits them and says how to follow them.
//
// The batch scripts come from templates a user can read (scripts/templates/slurm-array.sh,
// slurm-merge.sh), built into the program: each @NAME@ is replaced by its value, and a line
// whose placeholder has an empty value is left out (an #SBATCH option not given).
//
// Every Slurm command is run without a shell; a failure is reported with the command and
// what it printed (exit code 1), a missing command (no sbatch on PATH) as such.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace sg {

// The text of an embedded template (slurm-array.sh, slurm-merge.sh).
const std::string& slurm_template(const std::string& name);

// `text` with each @NAME@ of `values` replaced; a line that holds a placeholder whose value
// is empty is dropped. Throws sg::Error naming a placeholder left without a value.
std::string fill_template(const std::string& text, const std::map<std::string, std::string>& values,
                          const std::string& name);

// A shell word: as it is when it is safe, else in single quotes.
std::string shell_quote(const std::string& s);
std::string shell_join(const std::vector<std::string>& argv);

struct CommandOutput {
  int status = 0;       // exit status; 127 when the program is not found
  bool started = true;  // false: it could not be started (not found)
  std::string out, err;
};
// Runs argv[0] (looked up on PATH) with the arguments, standard input from /dev/null.
CommandOutput run_program(const std::vector<std::string>& argv);
// Runs it and returns its standard output; throws sg::Error "FLAG: `COMMAND` failed (exit
// N): MESSAGE" when it fails, "FLAG: sbatch: not found on PATH (...)" when it is missing.
std::string run_slurm(const std::vector<std::string>& argv, const std::string& flag);

// Throws the error of run_slurm for a missing command when `name` is not on PATH.
void require_program(const std::string& name, const std::string& flag);

// The options of a submission that the user gives.
struct SlurmOptions {
  bool submit = false;         // --slurm
  std::string partition;       // --partition
  int max_parallel = 0;        // --max-parallel (0: no cap)
  std::string time_per_task;   // --time-per-task (empty: from the estimate)
  bool requeue = false;        // --requeue
  int retries = 2;             // requeues of a failed task with --requeue
  bool assume_shared = false;  // --assume-shared
};

// Slurm's time format: minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS; throws
// sg::Error naming --time-per-task otherwise.
void check_slurm_time(const std::string& t);
// "D-HH:MM:SS" of at least a minute, rounded up to whole minutes.
std::string slurm_time(double seconds);

// "0-9%4", or "0,3,5-7" from sorted indices.
std::string array_spec(const std::vector<int>& indices, int max_parallel);

// Checks that every path (flag -> path) is on a filesystem the cluster's nodes share: a
// cluster whose only node is this machine shares everything; otherwise each path's
// filesystem must be a network or cluster one (NFS, Lustre, GPFS, BeeGFS, CephFS ...)
// unless `assume_shared`. Returns a line saying what was found; throws sg::Error naming the
// flag and the path.
std::string check_shared_folders(const std::vector<std::pair<std::string, std::string>>& paths,
                                 const std::string& partition, bool assume_shared);

// The filesystem type of the mount that holds `path` (/proc/self/mountinfo), and its mount
// point.
std::pair<std::string, std::string> filesystem_of(const std::string& path);

// The program's own path (/proc/self/exe) and the command line it was started with.
std::string program_path();
void set_program_arguments(int argc, char** argv);
const std::vector<std::string>& program_arguments();

// The program's arguments without the options of a submission (and `drop`, flag -> number
// of values), for the command a batch script runs.
std::vector<std::string> arguments_without(const std::vector<std::string>& args,
                                           const std::map<std::string, int>& drop);

// Jobs of this user still in the queue among `job_ids`: "ID STATE REASON" lines (squeue).
std::vector<std::string> queued_jobs(const std::vector<std::string>& job_ids);

// A submission's folder: FOLDER/N (created), N one more than the last there.
std::string next_submission_dir(const std::string& folder);
// "123" from sbatch --parsable's "123" or "123;cluster"; throws sg::Error naming `argv`.
std::string job_id(const std::string& out, const std::vector<std::string>& argv);

}  // namespace sg
