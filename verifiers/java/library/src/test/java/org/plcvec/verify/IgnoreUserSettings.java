package org.plcvec.verify;

import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

/**
 * The library's own tests are about the library, not about the settings of whoever builds it: a
 * {@code PLCVEC_*} variable in the builder's environment ({@code PLCVEC_VECTORS} pointing at a
 * copy, {@code PLCVEC_ID} narrowing a run) would change what they run. Before any test, each
 * setting's system property is set to nothing, which unsets its variable; a test that means a
 * setting gives it with {@link Environment#of}.
 */
public final class IgnoreUserSettings implements LauncherSessionListener {
    @Override
    public void launcherSessionOpened(LauncherSession session) {
        for (String name : SettingNames.SETTINGS) {
            System.setProperty(Environment.property(name), "");
        }
    }
}
