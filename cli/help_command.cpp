// fb89 help [COMMAND]: a command's help, the same text as `fb89 COMMAND --help`; alone, the
// same as `fb89 --help`. An unknown command is a usage error with the nearest known one.
#include <iostream>

#include "cli/commands.h"

namespace fb89::cli {

void register_help(CLI::App& app, int& exit_code) {
    auto command = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "help", "A command's help, as fb89 COMMAND --help gives it (alone: fb89 --help)");
    sub->add_option("command", *command, "The command (fb89 --help lists them)");
    sub->callback([&app, command, &exit_code] {
        // the text --help prints: the formatter's, under the name fb89 was called by
        if (command->empty()) {
            std::cout << app.get_formatter()->make_help(&app, app.get_name(),
                                                        CLI::AppFormatMode::Normal);
            exit_code = kSuccess;
            return;
        }
        std::vector<std::string> names;
        for (const CLI::App* s : app.get_subcommands({}))
            names.push_back(s->get_name());
        if (std::find(names.begin(), names.end(), *command) == names.end())
            throw UsageError("help: unknown command '" + *command + "'" +
                             nearest_hint(*command, names) + " (fb89 --help lists them)");
        std::cout << app.get_subcommand(*command)->help(app.get_name());
        exit_code = kSuccess;
    });
}

}  // namespace fb89::cli
