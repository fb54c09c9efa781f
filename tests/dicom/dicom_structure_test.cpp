// The structure walk made before DCMTK parses a file: nesting bounded, every length checked
// against the file, the file meta information well-formed; and the files that broke the import
// (that one bad file never ends an import's batch: tests/archive/archive_import_test.cpp).
#include <gtest/gtest.h>

#include <dcmtk/dcmdata/dcsequen.h>

#include <chrono>
#include <functional>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/utf8.h"
#include "dicom/dicom_fixture.h"
#include "dicom/dicom_header.h"
#include "dicom/dicom_slice_reader.h"
#include "dicom/dicom_structure.h"
#include "support/bad_dicom_files.h"

namespace maxillo {
namespace {

using testing::TemporaryFolder;

const std::filesystem::path kBadInputs = std::filesystem::path(MAXILLO_SOURCE_DIR) / "tests/data/bad-inputs";

ErrorCode header_error(const std::filesystem::path& file) {
  try {
    parse_instance_header(read_file(file), file);
  } catch (const Error& e) {
    EXPECT_TRUE(is_valid_utf8(e.reason())) << e.reason();
    return e.code();
  }
  ADD_FAILURE() << file << " was accepted";
  return ErrorCode::kProcessing;
}

// A copy of a good slice with `depth` sequences nested in one another (written by DCMTK).
std::filesystem::path with_nested_sequences(const std::filesystem::path& good, int depth,
                                            const std::filesystem::path& out,
                                            E_TransferSyntax syntax = EXS_LittleEndianExplicit) {
  DcmFileFormat file;
  file.loadFile(good.c_str());
  DcmItem* parent = file.getDataset();
  for (int level = 0; level < depth; ++level) {
    DcmItem* item = nullptr;
    parent->findOrCreateSequenceItem(DCM_ReferencedImageSequence, item, -2);
    parent = item;
  }
  parent->putAndInsertString(DCM_ReferencedSOPInstanceUID, "1.2.3");
  EXPECT_TRUE(file.saveFile(out.c_str(), syntax).good());
  return out;
}

TEST(DicomStructure, TheFilesThatBrokeTheImportAreRefusedQuicklyWithAReason) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(header_error(kBadInputs / "nested-seq-10000.dcm"), ErrorCode::kBadValue);
  EXPECT_EQ(header_error(kBadInputs / "hang-6GB-deflated-mutant.dcm"), ErrorCode::kNotDicom);
  EXPECT_EQ(header_error(kBadInputs / "json-utf8-rc60.dcm"), ErrorCode::kNotDicom);
  // Not a timing assertion: a hang would never get here, a blow-up would be killed.
  (void)start;
}

TEST(DicomStructure, NestingIsBoundedAndRealisticDepthsPass) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in", 1).files[0];
  for (auto syntax : {EXS_LittleEndianExplicit, EXS_LittleEndianImplicit, EXS_BigEndianExplicit}) {
    auto shallow = with_nested_sequences(good, kMaxSequenceNesting, folder / "shallow.dcm", syntax);
    EXPECT_NO_THROW(check_dicom_structure(read_file(shallow), shallow)) << int(syntax);
    EXPECT_EQ(parse_instance_header(read_file(shallow), shallow).sop_instance_uid,
              parse_instance_header(read_file(good), good).sop_instance_uid);
    auto deep = with_nested_sequences(good, kMaxSequenceNesting + 1, folder / "deep.dcm", syntax);
    EXPECT_EQ(header_error(deep), ErrorCode::kBadValue) << int(syntax);
  }
}

TEST(DicomStructure, EncodingsTheArchiveMeetsAllPass) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in", 1).files[0];
  for (auto syntax : {EXS_LittleEndianImplicit, EXS_BigEndianExplicit, EXS_DeflatedLittleEndianExplicit}) {
    DcmFileFormat file;
    file.loadFile(good.c_str());
    auto out = folder / ("syntax" + std::to_string(int(syntax)) + ".dcm");
    ASSERT_TRUE(file.saveFile(out.c_str(), syntax).good());
    EXPECT_NO_THROW(check_dicom_structure(read_file(out), out)) << int(syntax);
    EXPECT_EQ(read_dicom_slice(out).hu, read_dicom_slice(good).hu) << int(syntax);
  }
  testing::write_jpeg2000(good, folder / "j2k.dcm");  // encapsulated fragments walk too
  EXPECT_NO_THROW(check_dicom_structure(read_file(folder / "j2k.dcm"), folder / "j2k.dcm"));
}

TEST(DicomStructure, ALengthPastTheEndOfTheFileIsTruncationNamingTheElement) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in", 1).files[0];
  auto bytes = read_file(good);
  bytes.resize(bytes.size() - 100);
  try {
    check_dicom_structure(bytes, "cut.dcm");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kTruncated);
    EXPECT_NE(e.reason().find("(7FE0,0010)"), std::string::npos) << e.reason();
    EXPECT_NE(e.reason().find("at byte"), std::string::npos) << e.reason();
  }
}

// A Transfer Syntax UID with an empty component is not a UID: DCMTK would guess the data set's
// encoding, read lengths from the wrong bytes and allocate gigabytes (a fuzzing finding).
TEST(DicomStructure, ATransferSyntaxThatIsNotAUidIsRefusedBeforeDcmtkGuesses) {
  const auto file = std::filesystem::path(MAXILLO_SOURCE_DIR) /
                    "tests/fuzz/regressions/dicom_slice/transfer-syntax-with-an-empty-component.dcm";
  try {
    check_dicom_structure(read_file(file), file);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotDicom);
    EXPECT_NE(e.reason().find("Transfer Syntax UID (0002,0010) is not a UID"), std::string::npos) << e.reason();
  }
}

// A well-formed UID that names no transfer syntax DCMTK knows: DCMTK would guess the encoding
// from the data set's first bytes. This file's first group, 0x0800 read little endian, is 0x0008
// read big endian, so DCMTK guessed big endian, drifted into a value and allocated 2 GiB for the
// length it found there (a fuzzing finding). The walk refuses it before DCMTK reads it, and both
// readers say why.
TEST(DicomStructure, ATransferSyntaxDcmtkDoesNotKnowIsRefusedBeforeDcmtkGuessesItsEncoding) {
  const auto file = std::filesystem::path(MAXILLO_SOURCE_DIR) /
                    "tests/fuzz/regressions/dicom_header/unknown-transfer-syntax-guessed-big-endian.dcm";
  const auto bytes = read_file(file);
  for (const auto& read : std::vector<std::function<void()>>{[&] { check_dicom_structure(bytes, file); },
                                                             [&] { parse_instance_header(bytes, file); },
                                                             [&] { decode_dicom_slice(bytes, file); }}) {
    try {
      read();
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kUnsupportedSyntax);
      EXPECT_NE(e.reason().find("unknown transfer syntax 1.2.3.4"), std::string::npos) << e.reason();
      EXPECT_EQ(e.subject(), file.string());
    }
  }
}

TEST(DicomStructure, HugeRowsAndColumnsAreCheckedAgainstThePixelDataBeforeAllocating) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in", 1).files[0];
  DcmFileFormat file;
  file.loadFile(good.c_str());
  file.getDataset()->putAndInsertUint16(DCM_Rows, 65535);
  file.getDataset()->putAndInsertUint16(DCM_Columns, 65535);
  auto out = folder / "huge.dcm";
  ASSERT_TRUE(file.saveFile(out.c_str(), EXS_LittleEndianExplicit).good());
  try {
    read_dicom_slice(out);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    EXPECT_NE(e.reason().find("Rows x Columns needs"), std::string::npos) << e.reason();
  }
}

TEST(DicomStructure, Latin1TextWithoutACharacterSetIsReadAsLatin1) {
  TemporaryFolder folder;
  auto good = testing::write_series(folder / "in", 1).files[0];
  DcmFileFormat file;
  file.loadFile(good.c_str());
  file.getDataset()->findAndDeleteElement(DCM_SpecificCharacterSet);
  file.getDataset()->putAndInsertString(DCM_PatientName, "M\xFCller^J\xF6rg");  // Latin-1 bytes
  auto out = folder / "latin1.dcm";
  ASSERT_TRUE(file.saveFile(out.c_str(), EXS_LittleEndianExplicit).good());
  EXPECT_EQ(parse_instance_header(read_file(out), out).patient_name, "Müller^Jörg");
}

TEST(Utf8, ValidityAndTheLatin1Repair) {
  EXPECT_TRUE(is_valid_utf8("Müller-Łukasz^Zoë"));
  EXPECT_FALSE(is_valid_utf8("M\xFCller"));
  EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));          // overlong '/'
  EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));      // a surrogate
  EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // past U+10FFFF
  EXPECT_FALSE(is_valid_utf8("\xE2\x82"));          // cut short
  EXPECT_EQ(repaired_utf8("M\xFCller"), "Müller");
  EXPECT_EQ(repaired_utf8("Müller"), "Müller");
  std::string every_byte;
  for (int b = 1; b < 256; ++b) every_byte += char(b);
  EXPECT_TRUE(is_valid_utf8(repaired_utf8(every_byte)));
}

}  // namespace
}  // namespace maxillo
