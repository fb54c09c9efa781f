#include "bench/register_benchmark.h"

#include <algorithm>
#include <cmath>

#include "bench/formatted.h"
#include "bench/registration_benchmark.h"
#include "bench/shared_data.h"
#include "core/temporary_folder.h"
#include "core/volume_resample.h"
#include "validation/distance_statistics.h"

namespace maxillo::bench {
namespace {

// The median of the runs; of an even number of them, the mean of the middle two.
double median_of_runs(const std::vector<double>& values) { return validation::percentile(values, 50); }

Json runs_json(const MethodRuns& runs) {
  return {{"seconds", runs.seconds},
          {"rms_mm", runs.rms_mm},
          {"median_seconds", median_of_runs(runs.seconds)},
          {"median_rms_mm", median_of_runs(runs.rms_mm)}};
}

// Records in `benchmark` how far apart ours' answers lie (see RegisterBenchmark).
void measure_spread(const std::vector<Eigen::Isometry3d>& answers, const Eigen::MatrixX3d& skin,
                    RegisterBenchmark& benchmark) {
  for (const auto& answer : answers) {
    const Eigen::AngleAxisd between(answer.linear() * answers.front().linear().transpose());
    benchmark.spread_deg = std::max(benchmark.spread_deg, std::abs(between.angle()) * 180 / M_PI);
    benchmark.spread_mm = std::max(benchmark.spread_mm, rms_error_mm(skin, answer, answers.front().inverse()));
  }
}

std::string run_line(const RegisterBenchmark& b, size_t run) {
  std::string line = formatted("run %d: ours %.2f s, %d iterations, RMS %.4f mm", int(run + 1), b.ours.seconds[run],
                               b.iterations[run], b.ours.rms_mm[run]);
  if (b.elastix) line += formatted("; elastix %.2f s, RMS %.4f mm", b.elastix->seconds[run], b.elastix->rms_mm[run]);
  return line + "\n";
}

}  // namespace

RegisterBenchmark run_register_benchmark(const RegisterBenchOptions& options) {
  RegisterBenchmark benchmark;
  benchmark.options = options;
  const auto folder = (options.data.empty() ? shared_data_folder() / "cthead-stanford" : options.data) / "slices";
  if (!std::filesystem::exists(folder / "CThead.113")) {
    benchmark.skipped = "the cadaver head CT is not at " + folder.string() +
                        " (set MAXILLO_SHARED_DATA or --data to the folder holding cthead-stanford)";
    return benchmark;
  }
  const Volume fixed = read_cadaver_head(folder);
  const Eigen::Isometry3d known = known_rigid_move(fixed.geometry, options.rotation_deg, options.translation_mm);
  const Volume moving = resample_rigid(fixed, known, fixed.geometry);
  const Eigen::MatrixX3d skin = skin_vertices(fixed);
  benchmark.size = fixed.geometry.size;
  benchmark.box = cranial_registration_box(fixed);
  benchmark.skin_vertices = skin.rows();
  if (options.elastix && elastix_available()) benchmark.elastix.emplace();

  std::vector<Eigen::Isometry3d> answers;
  TemporaryFolder scratch("bench-register");
  for (int run = 0; run < options.runs; ++run) {
    RigidRegistrationOptions ours = options.ours;
    ours.box = benchmark.box;
    ours.seed = options.same_seed ? 1u : uint32_t(run + 1);
    const RigidRegistrationResult result = register_rigid(fixed, moving, ours);
    answers.push_back(result.moving_to_fixed);
    benchmark.ours.seconds.push_back(result.seconds);
    benchmark.ours.rms_mm.push_back(rms_error_mm(skin, result.moving_to_fixed, known));
    benchmark.iterations.push_back(result.iterations);
    if (!benchmark.elastix) continue;
    const auto e = run_elastix(fixed, moving, benchmark.box, scratch / ("elastix" + std::to_string(run)));
    benchmark.elastix->seconds.push_back(e->seconds);
    benchmark.elastix->rms_mm.push_back(rms_error_mm(skin, e->moving_to_fixed, known));
  }
  measure_spread(answers, skin, benchmark);
  return benchmark;
}

Json register_benchmark_json(const RegisterBenchmark& benchmark) {
  const RegisterBenchOptions& options = benchmark.options;
  Json json = {{"runs", options.runs},
               {"rotation_deg", options.rotation_deg},
               {"translation_mm", options.translation_mm},
               {"skin_vertices", benchmark.skin_vertices},
               {"ours", runs_json(benchmark.ours)},
               {"iterations", benchmark.iterations},
               {"threads", options.ours.threads},
               {"same_seed", options.same_seed},
               {"spread_deg", benchmark.spread_deg},
               {"spread_mm", benchmark.spread_mm}};
  if (benchmark.elastix) {
    json["elastix"] = runs_json(*benchmark.elastix);
    json["elastix_to_ours_time_ratio"] =
        median_of_runs(benchmark.elastix->seconds) / median_of_runs(benchmark.ours.seconds);
  }
  return json;
}

std::string register_benchmark_text(const RegisterBenchmark& b) {
  if (!b.skipped.empty()) return "skipped: " + b.skipped + "\n";
  std::string text =
      formatted("cadaver head %dx%dx%d, moved by %.1f deg and %.1f mm; %ld skin vertices; box z %.1f..%.1f mm\n",
                b.size.x(), b.size.y(), b.size.z(), b.options.rotation_deg, b.options.translation_mm,
                long(b.skin_vertices), b.box.min.z(), b.box.max.z());
  if (!b.elastix) text += "elastix: skipped (--no-elastix, or not on PATH)\n";
  for (size_t run = 0; run < b.ours.seconds.size(); ++run) text += run_line(b, run);
  text += formatted("ours:    median %.2f s, RMS %.4f mm over the skin (target <= 0.05 mm)\n",
                    median_of_runs(b.ours.seconds), median_of_runs(b.ours.rms_mm));
  text += formatted("ours:    runs %s apart by up to %.4f deg and %.4f mm over the skin\n",
                    b.options.same_seed ? "(same seed)" : "(seeds 1..n)", b.spread_deg, b.spread_mm);
  if (!b.elastix) return text;
  const double ratio = median_of_runs(b.elastix->seconds) / median_of_runs(b.ours.seconds);
  return text +
         formatted("elastix: median %.2f s, RMS %.4f mm over the skin\n", median_of_runs(b.elastix->seconds),
                   median_of_runs(b.elastix->rms_mm)) +
         formatted("time ratio elastix / ours: %.2f (target > 1)\n", ratio);
}

}  // namespace maxillo::bench
