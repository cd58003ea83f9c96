#include "app/cli.h"

#include "pipeline/dump.h"
#include "pipeline/error.h"
#include "pipeline/scene_io.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

namespace vplab {

namespace {

Scene sceneFrom(const std::string& path) { return path.empty() ? defaultScene() : loadScene(path); }

struct DumpOptions {
  std::string scene;
  std::string strategy = "npc";
  bool boundingBox = false;
  int indent = 2;
};

int runDump(const DumpOptions& d) {
  PipelineOptions options;
  options.strategy = *clipStrategyFromString(d.strategy);
  options.boundingBoxTest = d.boundingBox;
  const PipelineRun run = runPipeline(sceneFrom(d.scene), options);
  std::cout << dumpJson(run, d.indent);
  return 0;
}

struct ViewerOptions {
  std::string scene;
};

int runViewer(const ViewerOptions& v) {
  std::cerr << "vplab: the interactive viewer is not built yet; writing the pipeline dump of "
            << (v.scene.empty() ? "the default scene" : v.scene) << " instead\n";
  return runDump({v.scene, "npc", false, 2});
}

}  // namespace

int runCommandLine(int argc, char** argv) {
  CLI::App app{"vplab — Viewing Pipeline Lab: the 3D viewing pipeline (modeling, view orientation, "
               "view mapping, clipping in homogeneous coordinates, device mapping), step by step.\n"
               "Without a subcommand, opens the interactive viewer."};
  app.set_version_flag("--version", "vplab 0.1.0");

  ViewerOptions viewer;
  app.add_option("--scene", viewer.scene, "Scene file (JSON) to open; default: the built-in lecture scene")
      ->check(CLI::ExistingFile);

  DumpOptions dump;
  CLI::App* dumpCmd = app.add_subcommand("dump", "Run the CPU pipeline and print every stage's results as JSON");
  dumpCmd->add_option("--scene", dump.scene, "Scene file (JSON); default: the built-in lecture scene")
      ->check(CLI::ExistingFile);
  dumpCmd->add_option("--strategy", dump.strategy,
                      "Clipping strategy: npc (homogeneous NPC, the default), wc (the six frustum "
                      "planes in WC) or divide-first (wrong on purpose: divides by w before clipping)")
      ->check(CLI::IsMember({"npc", "wc", "divide-first"}));
  dumpCmd->add_flag("--bounding-box", dump.boundingBox,
                    "Decide whole objects by their bounding box first (seed 15.3.4)");
  dumpCmd->add_option("--indent", dump.indent, "JSON indentation; -1 prints everything on one line")
      ->check(CLI::Range(-1, 8));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (dumpCmd->parsed()) return runDump(dump);
    return runViewer(viewer);
  } catch (const Error& e) {
    std::cerr << "vplab: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "vplab: unexpected error: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace vplab
