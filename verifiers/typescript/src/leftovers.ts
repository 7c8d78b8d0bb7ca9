/**
 * What an implementation can leave behind in the test's own process that would hide or hold up
 * the verdict: descriptors it closed, and processes it started that keep the test's output open.
 *
 * An implementation runs in the test's process, so closing the descriptors it did not open
 * (3 and up) closes the event loop's own: the process then dies at the next turn of the loop,
 * before the test runner hears of the failure it was about to report. A failing vector's block is
 * therefore written at once, synchronously, when such damage is found.
 *
 * `node --test` reads each test file's output until every holder of it has closed it, so a process
 * the implementation started and left running with the inherited stdout holds the whole run up
 * for as long as it lives. When the test file's process ends, such processes (its own children
 * holding its stdout or stderr) are ended, with a note naming each.
 */
import { fstatSync, readdirSync, readFileSync, readlinkSync, writeSync } from "node:fs";

/** The descriptors above stderr the event loop lives on, open when the first vector was registered. */
let opened: readonly { readonly fd: number; readonly dev: number; readonly ino: number }[] | undefined;

/**
 * Note which descriptors the process holds before any implementation runs (once): the event
 * loop's own (epoll, eventfd, pipes, sockets). Files are left out: node and V8 open and close
 * some on threads of their own at any time (`/proc/self/maps`, read while the run goes on), and
 * one of them closing is no damage; counting it would print a failing vector's block twice.
 */
export function noteDescriptors(): void {
  if (opened !== undefined) return;
  const list: { fd: number; dev: number; ino: number }[] = [];
  for (const fd of candidateDescriptors()) {
    try {
      const s = fstatSync(fd);
      if (!s.isFile() && !s.isDirectory() && !s.isCharacterDevice() && !s.isBlockDevice()) list.push({ fd, dev: s.dev, ino: s.ino });
    } catch {
      // not open
    }
  }
  opened = list;
}

/**
 * The descriptors 3..1023 that may be open: those /proc/self/fd lists where the system has it (a
 * listing and a few fstat calls), else every number, each asked (an fstat that fails, with the
 * error node makes for it, for each of the thousand closed ones: some 6 ms a process).
 */
function candidateDescriptors(): number[] {
  try {
    return readdirSync("/proc/self/fd")
      .map(Number)
      .filter((fd) => Number.isInteger(fd) && fd >= 3 && fd < 1024)
      .sort((a, b) => a - b);
  } catch {
    return Array.from({ length: 1021 }, (_, i) => i + 3);
  }
}

/**
 * Whether a descriptor open before the run is closed now (an implementation closed what it did not
 * open), or its number now names something else (closed, then reused by the next file opened).
 */
export function descriptorsClosed(): boolean {
  for (const { fd, dev, ino } of opened ?? []) {
    try {
      const s = fstatSync(fd);
      if (s.dev !== dev || s.ino !== ino) return true;
    } catch {
      return true;
    }
  }
  return false;
}

/** What fd 1 and fd 2 of process `pid` are (a pipe's or a file's identity), where /proc tells. */
function outputsOf(pid: number | "self"): string[] {
  const out: string[] = [];
  for (const fd of [1, 2]) {
    try {
      out.push(readlinkSync(`/proc/${pid}/fd/${fd}`));
    } catch {
      // closed, or not this process's to read
    }
  }
  return out;
}

/**
 * End this process's children that hold its stdout or stderr (on Linux, through /proc; elsewhere
 * nothing is done), each named on stderr. Called as the test file's process ends under
 * `node --test`, whose wait for the output would otherwise last as long as they do.
 */
export function endChildrenHoldingOutput(): void {
  // node --test hands its test files a socket pair (a pipe elsewhere); a file or a terminal ends by itself.
  const mine = new Set(outputsOf("self").filter((l) => l.startsWith("socket:") || l.startsWith("pipe:")));
  if (mine.size === 0) return;
  let entries: string[];
  try {
    entries = readdirSync("/proc");
  } catch {
    return;
  }
  for (const entry of entries) {
    if (!/^\d+$/.test(entry)) continue;
    let stat: string;
    try {
      stat = readFileSync(`/proc/${entry}/stat`, "utf8");
    } catch {
      continue;
    }
    // pid (comm) state ppid ...: comm may hold spaces and parentheses, so read from the last ")".
    const close = stat.lastIndexOf(")");
    const ppid = Number(stat.slice(close + 2).split(" ")[1]);
    if (ppid !== process.pid || !outputsOf(Number(entry)).some((l) => mine.has(l))) continue;
    const comm = stat.slice(stat.indexOf("(") + 1, close);
    try {
      process.kill(Number(entry), "SIGKILL");
      writeSync(2, `plcvec: ended process ${entry} (${comm}), which the implementation started and left holding the test's output\n`);
    } catch {
      // gone already
    }
  }
}
