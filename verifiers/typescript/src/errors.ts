/** A problem with the suite's input (a vector file, an expectations file, a selection): never a traceback. */
export class VerifyError extends Error {
  override readonly name = "VerifyError";
}
