-- Schema version 3: work shared between processes and nodes (`nightly --claim`).
-- An item is offered once (its name carries what it depends on, e.g. a case and its inputs'
-- hash), claimed by one worker at a time under a lease, and finished once. A worker that dies
-- keeps its lease only until expires_at; then another worker claims the item.
-- Leases are coordination, not data: this table is not journalled and a rebuilt index starts
-- it empty (the next run offers the items again; finished work is known by its artefacts).
CREATE TABLE work_queue (
  queue       TEXT NOT NULL,
  item        TEXT NOT NULL,
  state       TEXT NOT NULL DEFAULT 'pending',  -- 'pending', 'done', 'failed', 'superseded'
  holder      TEXT NOT NULL DEFAULT '',         -- the worker holding or last holding the lease
  expires_at  BIGINT NOT NULL DEFAULT 0,        -- lease end, Unix seconds; 0: never leased
  claims      INTEGER NOT NULL DEFAULT 0,       -- how many leases were taken on it
  reason      TEXT NOT NULL DEFAULT '',         -- why it failed or was superseded
  PRIMARY KEY (queue, item)
);
