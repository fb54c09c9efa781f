-- Schema version 2: the index journal (src/archive/index_journal.h).
-- journal_sequence is the number of the last journal entry the index has committed: entries
-- 1..journal_sequence under OBJECTS/journal/ are its history, from which it can be rebuilt.
-- An archive upgraded from version 1 gets one "snapshot" entry holding its rows at the upgrade.
CREATE TABLE index_state (
  id                INTEGER PRIMARY KEY CHECK (id = 1),
  journal_sequence  INTEGER NOT NULL
);
INSERT INTO index_state(id, journal_sequence) VALUES (1, 0);
