// fb89: one executable, one subcommand per file in cli/.
#include <algorithm>
#include <csignal>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "controller_sim/profile.h"
#include "frontend/data_dir.h"
#include "frontend/names.h"
#include "frontend/option_limits.h"
#include "host/scene/scene_error.h"
#include "protocol/output_file.h"
#include "protocol/stream_reader.h"

namespace {

// "--repeat: 1.5 is not an integer" for the first integer option whose given value is not
// one, else nothing. (CLI11 keeps what was given as text, checked or not.)
std::optional<std::string> not_an_integer(const CLI::App& command) {
    for (const CLI::Option* o : command.get_options()) {
        const std::string type = o->get_type_name();
        if (type.rfind("INT", 0) != 0 && type.rfind("UINT", 0) != 0) continue;
        for (const std::string& given : o->results()) {
            std::size_t digits = given.size();
            try {
                (void)std::stoll(given, &digits);
            } catch (const std::exception&) {
                digits = 0;
            }
            if (given.empty() || digits != given.size())
                return o->get_name() + ": " + given + " is not an integer";
        }
    }
    return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace fb89::cli;
    // A file size limit (ulimit -f) then fails the write with EFBIG, which every writer
    // reports naming the file, instead of killing fb89 with a half-written temporary.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{
        "fb89: image and intervisibility coherence in rendering, on an emulated 1989 "
        "graphics pipeline (Marks, Walsh, Christensen & Friedell, GI '90)"};
    app.set_version_flag("-V,--version", std::string("fb89 ") + FB89_VERSION);
    app.require_subcommand(1);
    app.fallthrough();

    int exit_code = kSuccess;
    register_render(app, exit_code);
    register_model(app, exit_code);
    register_experiment(app, exit_code);
    register_sweep(app, exit_code);
    register_compare(app, exit_code);
    register_calibrate(app, exit_code);
    register_replay(app, exit_code);
    register_dump(app, exit_code);
    register_info(app, exit_code);
    register_trim(app, exit_code);
    register_diff(app, exit_code);
    register_controller(app, exit_code);
    register_view(app, exit_code);
    register_radiosity(app, exit_code);
    register_host_run(app, exit_code);
    register_host_validate(app, exit_code);
    register_controller_validate(app, exit_code);
    register_list(app, exit_code);
    register_help(app, exit_code);
    app.footer(names_summary());
    use_installed_period_parts();

    // no command at all: say how to start
    if (argc == 1) {
        std::cerr << "fb89: usage: fb89 COMMAND [OPTIONS], e.g. `fb89 render demo`; "
                     "`fb89 --help` lists the commands, `fb89 help COMMAND` a command's "
                     "options, `fb89 list` the methods, hosts, scenes and experiments\n";
        return kBadInput;
    }
    // an unknown command: say so, and the nearest known one
    if (argc > 1 && argv[1][0] != '-') {
        std::vector<std::string> names;
        for (const CLI::App* sub : app.get_subcommands({}))
            names.push_back(sub->get_name());
        if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
            // "version" and "help" are near the options that do it
            std::vector<std::string> near = names;
            near.insert(near.end(), {"--version", "--help"});
            std::cerr << "fb89: usage: unknown command '" << argv[1] << "'"
                      << nearest_hint(argv[1], near) << " (fb89 --help lists them)\n";
            return kBadInput;
        }
    }

    // every output file the command writes is put in place when it succeeds (or finds a
    // difference: exit 1), and none when it fails (protocol/output_file.h)
    fb89::protocol::OutputBatch outputs;
    try {
        app.parse(argc, argv);
        if (exit_code == kSuccess || exit_code == kCheckFailed) outputs.publish();
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version
    } catch (const CLI::ParseError& e) {
        // an option the command does not know: one line each, with the nearest it does know
        if (dynamic_cast<const CLI::ExtrasError*>(&e) && argc > 1 && argv[1][0] != '-') {
            const std::string command = argv[1];
            std::vector<std::string> options;
            for (const CLI::Option* o : app.get_subcommand(command)->get_options())
                for (const std::string& name : o->get_lnames())
                    options.push_back("--" + name);
            bool said = false;
            for (int i = 2; i < argc; ++i) {
                const std::string word = argv[i];
                if (word.rfind("--", 0) != 0) continue;
                const std::string given = word.substr(0, word.find('='));
                if (std::find(options.begin(), options.end(), given) != options.end()) continue;
                std::cerr << "fb89: usage: " << command << ": unknown option '" << given << "'"
                          << nearest_hint(given, options) << " (fb89 " << command
                          << " --help lists them)\n";
                said = true;
            }
            if (said) return kBadInput;
        }
        // CLI11's problems in fb89's words (frontend/option_limits.h), said as fb89 says every
        // usage error: one line, and where to look
        const bool command = argc > 1 && argv[1][0] != '-';
        // an integer option given a fraction or a word: say that, not "not in range"
        if (command && app.get_subcommand(argv[1])->parsed())
            if (const auto what = not_an_integer(*app.get_subcommand(argv[1]))) {
                std::cerr << "fb89: usage: " << argv[1] << ": " << *what << " (fb89 " << argv[1]
                          << " --help says more)\n";
                return kBadInput;
            }
        std::cerr << "fb89: usage: " << (command ? std::string(argv[1]) + ": " : "")
                  << fb89::frontend::with_nearest_name(fb89::frontend::usage_words(e.what()))
                  << " (fb89 " << (command ? std::string(argv[1]) + " " : "")
                  << "--help says more)\n";
        return kBadInput;
    } catch (const UsageError& e) {
        // a name among others it might have been: the nearest of them too
        std::cerr << "fb89: usage: " << fb89::frontend::with_nearest_name(e.what()) << "\n";
        return kBadInput;
    } catch (const fb89::host::SceneError& e) {
        std::cerr << "fb89: error: " << e.what() << "\n";
        return kBadInput;
    } catch (const std::exception& e) {
        std::cerr << "fb89: error: " << e.what() << "\n";
        return kBadInput;
    }
    return exit_code;
}
