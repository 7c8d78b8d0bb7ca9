// The API Extractor report of each given package folder (its dist/src/index.d.ts), written to
// <folder>/dist/api/plcvec.api.md: one process for all of them, so the tool starts once.
//
//     node api/report.mjs FOLDER [FOLDER ...]
import { Extractor, ExtractorConfig } from "@microsoft/api-extractor";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const config = join(dirname(fileURLToPath(import.meta.url)), "api-extractor.json");
let failed = false;
for (const folder of process.argv.slice(2)) {
  const loaded = ExtractorConfig.loadFile(config);
  const prepared = ExtractorConfig.prepare({
    configObject: { ...loaded, projectFolder: folder },
    configObjectFullPath: config,
    packageJsonFullPath: join(folder, "package.json"),
  });
  const result = Extractor.invoke(prepared, { localBuild: true, showVerboseMessages: false, messageCallback: (m) => (m.handled = m.logLevel !== "error") });
  if (!result.succeeded) {
    console.error(`api/report.mjs: API Extractor failed on ${folder} (${result.errorCount} errors)`);
    failed = true;
  }
}
process.exitCode = failed ? 1 : 0;
