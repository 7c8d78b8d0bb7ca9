/**
 * A problem with the suite's input (a vector file, an expectations file, a selection, a
 * PLCVEC_* variable): never a traceback. Its stack is its message alone, so that a test runner
 * that prints a thrown error (Vitest, Jest collecting `cases()`) shows the file and line, or the
 * variable, and no frames of plcvec's own code.
 */
export class VerifyError extends Error {
  override readonly name = "VerifyError";
  constructor(message: string) {
    super(message);
    this.stack = `${this.name}: ${message}`;
  }
}
