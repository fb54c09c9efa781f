-- Schema version 1 of the maxillo archive.
-- Applied in one transaction by the archive, which then sets PRAGMA user_version = 1.
-- Dates are DICOM DA (YYYYMMDD), times DICOM TM; *_at columns are UTC ISO 8601.
-- Lengths in millimetres. Multi-valued DICOM attributes keep DICOM's backslash separator.

CREATE TABLE patients (
  id          INTEGER PRIMARY KEY,
  patient_id  TEXT NOT NULL UNIQUE,         -- (0010,0020), the key
  name        TEXT NOT NULL DEFAULT '',     -- (0010,0010), UTF-8, as first archived
  birth_date  TEXT NOT NULL DEFAULT '',     -- (0010,0030)
  sex         TEXT NOT NULL DEFAULT '',     -- (0010,0040)
  created_at  TEXT NOT NULL
);

CREATE TABLE studies (
  id           INTEGER PRIMARY KEY,
  patient      INTEGER NOT NULL REFERENCES patients(id),
  study_uid    TEXT NOT NULL UNIQUE,
  date         TEXT NOT NULL DEFAULT '',
  time         TEXT NOT NULL DEFAULT '',
  description  TEXT NOT NULL DEFAULT '',
  accession    TEXT NOT NULL DEFAULT ''
);
CREATE INDEX studies_patient ON studies(patient);

CREATE TABLE series (
  id                    INTEGER PRIMARY KEY,
  study                 INTEGER NOT NULL REFERENCES studies(id),
  series_uid            TEXT NOT NULL UNIQUE,
  modality              TEXT NOT NULL DEFAULT '',
  description           TEXT NOT NULL DEFAULT '',
  number                INTEGER,
  rows                  INTEGER,
  columns               INTEGER,
  pixel_spacing_row     REAL,   -- mm between rows (first value of Pixel Spacing)
  pixel_spacing_column  REAL,   -- mm between columns
  slice_thickness       REAL    -- mm
);
CREATE INDEX series_study ON series(study);

-- Content-addressed files under objects/<first 2 hex>/<other 62 hex>.
CREATE TABLE objects (
  sha256  TEXT PRIMARY KEY,
  size    INTEGER NOT NULL
) WITHOUT ROWID;

CREATE TABLE instances (
  id                 INTEGER PRIMARY KEY,
  series             INTEGER NOT NULL REFERENCES series(id),
  sop_instance_uid   TEXT NOT NULL UNIQUE,
  sop_class_uid      TEXT NOT NULL DEFAULT '',
  instance_number    INTEGER,
  image_position     TEXT NOT NULL DEFAULT '',  -- (0020,0032) x\y\z, mm, LPS
  image_orientation  TEXT NOT NULL DEFAULT '',  -- (0020,0037) row\column direction cosines
  transfer_syntax    TEXT NOT NULL,
  object             TEXT NOT NULL REFERENCES objects(sha256),
  size               INTEGER NOT NULL,
  source_path        TEXT NOT NULL,
  imported_at        TEXT NOT NULL
);
CREATE INDEX instances_series ON instances(series, instance_number);
CREATE INDEX instances_object ON instances(object);

-- A patient ID that arrived with another name, birth date or sex than archived: kept, not merged.
CREATE TABLE identity_flags (
  id                INTEGER PRIMARY KEY,
  patient           INTEGER NOT NULL REFERENCES patients(id),
  attribute         TEXT NOT NULL,  -- 'name', 'birth_date' or 'sex'
  archived_value    TEXT NOT NULL,
  arrived_value     TEXT NOT NULL,
  source_path       TEXT NOT NULL,  -- the first file that brought the differing value
  sop_instance_uid  TEXT NOT NULL,
  flagged_at        TEXT NOT NULL,
  UNIQUE (patient, attribute, arrived_value)
);

-- The unit of work. One case per patient, label 'default', is created at first import.
CREATE TABLE cases (
  id          INTEGER PRIMARY KEY,
  patient     INTEGER NOT NULL REFERENCES patients(id),
  label       TEXT NOT NULL DEFAULT 'default',
  created_at  TEXT NOT NULL,
  UNIQUE (patient, label)
);

CREATE TABLE case_series (
  case_id  INTEGER NOT NULL REFERENCES cases(id),
  series   INTEGER NOT NULL REFERENCES series(id),
  role     TEXT NOT NULL,  -- 'preop' (first CT series), 'postop', 'follow-up', 'unassigned'
  PRIMARY KEY (case_id, series)
) WITHOUT ROWID;

-- Derived objects (reports, renders, surfaces...) with what they were made from.
CREATE TABLE artefacts (
  id               INTEGER PRIMARY KEY,
  case_id          INTEGER NOT NULL REFERENCES cases(id),
  kind             TEXT NOT NULL,
  object           TEXT NOT NULL REFERENCES objects(sha256),
  media_type       TEXT NOT NULL,
  inputs_hash      TEXT NOT NULL,
  parameters       TEXT NOT NULL DEFAULT '{}',  -- JSON
  program_version  TEXT NOT NULL,
  created_at       TEXT NOT NULL
);
CREATE INDEX artefacts_lookup ON artefacts(case_id, kind, inputs_hash, id);
