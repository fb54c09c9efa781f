#include <array>

#include "cli/command.h"

namespace maxillo::cli {

// One declaration per cmd_<name>.cpp.
void attach_version(CLI::App&, CommandContext&);
void attach_import(CLI::App&, CommandContext&);
void attach_list(CLI::App&, CommandContext&);
void attach_show(CLI::App&, CommandContext&);
void attach_verify(CLI::App&, CommandContext&);
void attach_archive(CLI::App&, CommandContext&);
void attach_export(CLI::App&, CommandContext&);
void attach_bench(CLI::App&, CommandContext&);
void attach_surfaces(CLI::App&, CommandContext&);
void attach_convert(CLI::App&, CommandContext&);
void attach_report(CLI::App&, CommandContext&);
void attach_demo(CLI::App&, CommandContext&);
void attach_sample(CLI::App&, CommandContext&);
void attach_occlude(CLI::App&, CommandContext&);
void attach_dental(CLI::App&, CommandContext&);
void attach_ceph(CLI::App&, CommandContext&);
void attach_landmarks(CLI::App&, CommandContext&);
void attach_followup(CLI::App&, CommandContext&);
void attach_plan(CLI::App&, CommandContext&);
void attach_simulate(CLI::App&, CommandContext&);
void attach_register(CLI::App&, CommandContext&);
void attach_validate(CLI::App&, CommandContext&);
void attach_nightly(CLI::App&, CommandContext&);
void attach_sample_postop(CLI::App&, CommandContext&);
void attach_role(CLI::App&, CommandContext&);
void attach_orientation(CLI::App&, CommandContext&);
void attach_serve(CLI::App&, CommandContext&);
void attach_echo(CLI::App&, CommandContext&);
void attach_send(CLI::App&, CommandContext&);
void attach_find(CLI::App&, CommandContext&);
void attach_retrieve(CLI::App&, CommandContext&);

std::span<const CommandSpec> command_table() {
  static const std::array kCommands = {
      CommandSpec{"version", "General", "print the program version", attach_version},
      CommandSpec{"import", "Archive", "archive DICOM files or folders (recursive)", attach_import},
      CommandSpec{"list", "Archive", "list patients, studies, series, cases or identity flags", attach_list},
      CommandSpec{"show", "Archive", "show a patient, study, series, instance or case by ID or UID", attach_show},
      CommandSpec{"verify", "Archive", "check the index and re-hash every object; --repair quarantines orphans",
                  attach_verify},
      CommandSpec{"archive", "Archive",
                  "archive maintenance: rebuild-index (a lost or damaged index from the object store), migrate (to "
                  "a PostgreSQL index with a shared object folder)",
                  attach_archive},
      CommandSpec{"role", "Archive", "set a series' role in its case (preop, postop, follow-up, unassigned)",
                  attach_role},
      CommandSpec{"orientation", "Archive",
                  "does the case's CT header agree with the anatomy (face anterior, vertex superior); --confirm",
                  attach_orientation},
      CommandSpec{"export", "Archive", "write a series' original files into a folder", attach_export},
      CommandSpec{"bench", "Archive", "benchmarks (bench import, bench cube, bench occlusion)", attach_bench},
      CommandSpec{"serve", "Network", "DICOM storage server: archive what scanners and PACS send (C-STORE, C-ECHO)",
                  attach_serve},
      CommandSpec{"send", "Network", "C-STORE series, studies or a case's reports to a PACS (--deidentify for copies)",
                  attach_send},
      CommandSpec{"find", "Network", "C-FIND the studies a PACS holds (patient, name, date, modality)", attach_find},
      CommandSpec{"retrieve", "Network", "C-GET (or C-MOVE, --move-port) studies from a PACS into the archive",
                  attach_retrieve},
      CommandSpec{"echo", "Network", "C-ECHO a DICOM peer: AE@HOST:PORT", attach_echo},
      CommandSpec{"surfaces", "Imaging", "skin and bone surfaces from a DICOM series", attach_surfaces},
      CommandSpec{"convert", "Imaging", "wrap a MetaImage/NRRD volume as a DICOM CT series", attach_convert},
      CommandSpec{"register", "Imaging",
                  "rigid registration of a post-operative CT to the pre-operative CT (mutual information)",
                  attach_register},
      CommandSpec{"report", "Reports", "consultation report of a case as PDF", attach_report},
      CommandSpec{"landmarks", "Cephalometry",
                  "find the cephalometric landmarks automatically (landmarks detect), with confidences and checks",
                  attach_landmarks},
      CommandSpec{"ceph", "Cephalometry", "cephalometric measurements, time points, ISBI check", attach_ceph},
      CommandSpec{"followup", "Cephalometry", "follow-up tables of a case or a cohort CSV", attach_followup},
      CommandSpec{"sample", "General", "write the synthetic phantom: DICOM CT series and landmarks", attach_sample},
      CommandSpec{"plan", "Planning",
                  "surgical plan of a case: create, show, apply (distraction vectors, checks, schedule)", attach_plan},
      CommandSpec{"simulate", "Planning", "soft-tissue prediction: the face after a plan's bone moves (mtm, fem, msm)",
                  attach_simulate},
      CommandSpec{"validate", "Validation",
                  "a case's prediction against its post-operative CT: distances, error map, profiles", attach_validate},
      CommandSpec{"nightly", "Validation",
                  "validate every case with a post-operative CT and a plan; summary PDF (--shard i/n, or --claim "
                  "for workers sharing the archive's queue, then --summary-only)",
                  attach_nightly},
      CommandSpec{"sample-postop", "Validation", "synthetic post-operative CT of a planned case, with the known answer",
                  attach_sample_postop},
      CommandSpec{"occlude", "Planning", "virtual occlusion: guided alignment of the dental arches, occlusionogram",
                  attach_occlude},
      CommandSpec{"dental", "Planning", "a patient's dental scans: import, register onto the CT's teeth, show",
                  attach_dental},
      CommandSpec{"demo", "General", "the whole pipeline on the synthetic phantom, ending in a PDF report",
                  attach_demo},
  };
  return kCommands;
}

}  // namespace maxillo::cli
