#pragma once
// The CPU time an index server has spent, for benchmarks that report the server's share of the
// work apart from the clients' (issue 31). Read from /proc: the server's postmaster (its own and
// its reaped backends' time) and every backend still running, so it is known only for a server
// on this machine that this user may read.
#include <optional>
#include <string>

namespace maxillo {

// `database`: a full database address (postgresql://USER@HOST:PORT/DB). Seconds of user and
// system time of the whole server since it started; nothing when its processes are not visible
// here (another machine, a container). Take the difference of two readings.
std::optional<double> server_cpu_seconds(const std::string& database);

}  // namespace maxillo
