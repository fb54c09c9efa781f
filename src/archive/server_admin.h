#pragma once
// Administration statements on an index server, for benchmarks and tools that make and drop
// whole archive databases: `server` is an address without a database
// (postgresql://USER@HOST:PORT/); the statement runs in its maintenance database "postgres".
#include <string>

namespace maxillo {

// Throws Error(kArchiveUnreachable or kDatabase) naming the server.
void run_on_server(const std::string& server, const std::string& sql);

}  // namespace maxillo
