"""How long the live tests wait for an event (a line, a message, a page state, a process's exit)
before they call it lost. The tests wait for events, never for a window of time: this bound only
ends a hang, so it is far above any wait on a loaded machine or under the sanitizers (a cold
kernel build took over 60 s under load). TEXCC_TEST_WAIT_S overrides it."""
import os

WAIT_S = float(os.environ.get("TEXCC_TEST_WAIT_S", "600"))
