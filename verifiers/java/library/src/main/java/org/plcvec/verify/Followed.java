package org.plcvec.verify;

import java.util.List;

/**
 * One interpretation as a run follows it: the alternative, whether the implementation declared it
 * (else it is the default), and the families whose vectors it may decide.
 */
public record Followed(String alternative, boolean declared, List<String> families) {
}
