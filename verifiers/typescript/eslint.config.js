// ESLint (flat config) with typescript-eslint's strict rules over the sources, tests and examples.
import eslint from "@eslint/js";
import tseslint from "typescript-eslint";

import globals from "globals";

export default tseslint.config(
  { ignores: ["dist/", "node_modules/", "vectors/"] },
  eslint.configs.recommended,
  ...tseslint.configs.strict,
  // Plain scripts run by node (api/report.mjs): node's globals.
  { files: ["**/*.mjs"], languageOptions: { globals: globals.node } },
  {
    rules: {
      // A function is read in one go: the house's bound (the generated names are data, not functions).
      "max-lines-per-function": ["error", { max: 80 }],
      // `_`-prefixed names are deliberately unused (a destructured field left out of a copy).
      "@typescript-eslint/no-unused-vars": ["error", { argsIgnorePattern: "^_", varsIgnorePattern: "^_" }],
      // Indexing is checked by noUncheckedIndexedAccess; `!` after such a check is the idiom.
      "@typescript-eslint/no-non-null-assertion": "off",
    },
  },
);
