#pragma once
// De-identified copies of DICOM files for research and teaching exports, after the Basic
// Application Level Confidentiality Profile of DICOM PS3.15 E.1 with two of its options:
// "Retain Longitudinal Temporal Information" (study and series dates stay, so follow-up
// intervals survive) and "Retain Patient Characteristics" (sex, age, size, weight stay).
//
// Identifying attributes are removed or emptied; private attributes are removed; the Patient ID
// and name become a pseudonym and every UID a new one. Pseudonyms and UIDs are keyed hashes
// (SHA-256 of a secret and the original), so the same patient and the same study map to the
// same pseudonym in every export made with the same secret (follow-up series stay linked),
// while nobody without the secret can recover or confirm an original ID by trying candidates.
// Pixel data are untouched: burnt-in text is not detected (CT slices have none), but a file that
// says it has some (Burned In Annotation YES) is refused, and so is an encapsulated document
// (e.g. an Encapsulated PDF report), whose content names the patient: Error(kCannotDeidentify).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace maxillo {

// "ANON-" + 12 hex characters, a function of (secret, patient_id) only.
std::string pseudonym_for(std::string_view secret, std::string_view patient_id);

// "2.25." + a 128-bit decimal number, a function of (secret, uid) only (PS3.5 B.2 UUID form).
std::string pseudonymous_uid(std::string_view secret, std::string_view uid);

// Reads the DICOM file `source` and writes its de-identified copy to `target` atomically.
// Returns the copy's SOP Instance UID. Throws Error(NotDicom / CannotDeidentify / WriteFailed)
// naming the file.
std::string write_deidentified_copy(const std::filesystem::path& source, const std::filesystem::path& target,
                                    std::string_view secret);

}  // namespace maxillo
