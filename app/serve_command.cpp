// `vibro serve`: the HTTP service of API.md and the web page, until SIGINT or SIGTERM.
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.h"
#include "server/flags.h"
#include "server/service.h"
#include "server/stop_signals.h"

namespace vibro {

int serve_command(const Args& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << "usage: vibro serve [flags]\n" << server::flags_help();
    return 0;
  }
  const server::ConfigOrError parsed = server::config_from_flags(args);
  if (const auto* e = std::get_if<FieldError>(&parsed)) {
    std::cerr << nlohmann::json{{"error", e->message}, {"field", e->field}}.dump() << "\n";
    return 2;
  }
  const server::ServerConfig& config = std::get<server::ServerConfig>(parsed);
  server::Service service(config);
  std::string error;
  if (!service.warm_up(error)) {
    std::cerr << "vibro serve: the paper scene does not render: " << error << "\n";
    return 1;
  }
  const int port = service.bind();
  if (port < 0) {
    std::cerr << "vibro serve: cannot listen on " << config.host << ":" << config.port << "\n";
    return 1;
  }
  server::StopOnSignals stop_on_signals([&service] { service.stop(); });
  std::cout << "vibro serve: http://" << config.host << ":" << port << "/ (paper scene ready)"
            << std::endl;
  return service.serve() ? 0 : 1;
}

}  // namespace vibro
