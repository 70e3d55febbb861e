// The `raster` commands: one record per command, in the order `raster --help` lists them.
// The record is all the command line knows of a command: cli::run (command_line.h) makes a
// CLI11 subcommand of each, names them in the help's footer and in the error for an unknown
// command, and runs the one the command line chose.
//
// Adding a command is one row in the table of commands.cpp, and a folder apps/NAME/ with its
// arguments (NAMEArgs), addNAMEOptions and runNAME.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace cli {

// Runs the command chosen with the options parsed; returns the exit status. Bad input
// throws UsageError (exit 2).
using CommandRun = std::function<int()>;

struct Command {
  const char* name;   // raster NAME
  const char* help;   // its line in `raster --help`
  // Adds the command's options to its subcommand, bound to arguments the returned run owns
  // (commands.cpp: withArgs), before the command line is parsed.
  CommandRun (*addOptions)(CLI::App& command);
};

// Every command, in order.
const std::vector<Command>& commands();

// The command named `name`, or nullptr.
const Command* findCommand(const std::string& name);

// "render, compare, ...": the names for a message.
std::string commandList();

}  // namespace cli
