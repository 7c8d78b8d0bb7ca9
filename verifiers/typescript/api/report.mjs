// The API Extractor report of every entry point of each given package folder (each subpath of its
// package.json's "exports" with a "types" file), written to <folder>/dist/api/: plcvec.api.md for
// the main entry ("."), plcvec-reference.api.md for "./reference", and so on. One process for all of
// them, so the tool starts once; and one TypeScript program per folder (API Extractor's CompilerState,
// made with every entry point of the folder), which each entry point's report reads, instead of the
// program each report would otherwise build anew (parsing @types/node and the package's declarations
// again for every entry point).
//
//     node api/report.mjs FOLDER [FOLDER ...]
import { CompilerState, Extractor, ExtractorConfig } from "@microsoft/api-extractor";
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const config = join(dirname(fileURLToPath(import.meta.url)), "api-extractor.json");

/** [report file name, declarations file] of each entry point of the package in `folder`. */
function entryPoints(folder) {
  const exports = JSON.parse(readFileSync(join(folder, "package.json"), "utf8")).exports ?? {};
  return Object.entries(exports)
    .filter(([, target]) => typeof target === "object" && target !== null && typeof target.types === "string")
    .map(([subpath, target]) => [`plcvec${subpath.slice(1).replace(/[^A-Za-z0-9]+/g, "-")}.api.md`, join(folder, target.types)]);
}

let failed = false;
for (const folder of process.argv.slice(2)) {
  const entries = entryPoints(folder).map(([reportFileName, entry]) => {
    const loaded = ExtractorConfig.loadFile(config);
    const prepared = ExtractorConfig.prepare({
      configObject: { ...loaded, projectFolder: folder, mainEntryPointFilePath: entry, apiReport: { ...loaded.apiReport, reportFileName } },
      configObjectFullPath: config,
      packageJsonFullPath: join(folder, "package.json"),
    });
    return [entry, prepared];
  });
  if (entries.length === 0) continue;
  const compilerState = CompilerState.create(entries[0][1], { additionalEntryPoints: entries.map(([entry]) => entry) });
  for (const [entry, prepared] of entries) {
    const result = Extractor.invoke(prepared, { localBuild: true, compilerState, showVerboseMessages: false, messageCallback: (m) => (m.handled = m.logLevel !== "error") });
    if (!result.succeeded) {
      console.error(`api/report.mjs: API Extractor failed on ${entry} (${result.errorCount} errors)`);
      failed = true;
    }
  }
}
process.exitCode = failed ? 1 : 0;
