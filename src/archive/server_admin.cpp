#include "archive/server_admin.h"

#include "archive/postgres.h"
#include "core/error.h"

namespace maxillo {

void run_on_server(const std::string& server, const std::string& sql) {
  if (!server.ends_with("/"))
    throw Error(ErrorCode::kBadArchiveAddress, server, "a server address ends with '/' (postgresql://USER@HOST:PORT/)");
  postgres::Connection connection(server + "postgres");
  connection.execute(sql);
}

}  // namespace maxillo
