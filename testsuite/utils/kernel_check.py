"""A lit test format that also checks the kernels a test leaves behind.

Every OpenCL kernel texcc emits in the tests must pass
`clang-15 -x cl -cl-std=CL1.2 -fsyntax-only` (issue 3). Rather than a RUN line in each test,
KernelCheckedShTest runs a test as lit's ShTest does and, when it passed, syntax-checks every
`proctex*.cl` under the test's %t. A test that leaves a deliberately broken kernel there says
`NO-KERNEL-CHECK` in its text.

Many tests leave the same kernel (a library texture compiled alike): a kernel that passed is
remembered by the SHA-256 of its bytes and of the clang command, under the suite's exec root
(.kernel-check/), and not checked again; a failing one is checked every time.
"""
import hashlib
import os
import subprocess

import lit.Test
import lit.TestRunner
from lit.formats import ShTest


class KernelCheckedShTest(ShTest):
    def __init__(self, clang, execute_external):
        super().__init__(execute_external)
        self.clang = clang

    def execute(self, test, litConfig):
        result = super().execute(test, litConfig)
        if result.code != lit.Test.PASS:
            return result
        with open(test.getSourcePath(), errors="replace") as f:
            if "NO-KERNEL-CHECK" in f.read():
                return result
        _, tmp_base = lit.TestRunner.getTempPaths(test)
        passed_dir = os.path.join(test.suite.exec_root, ".kernel-check")
        for kernel in _kernels_under(tmp_base + ".tmp"):
            failure = self._syntax_error(kernel, passed_dir)
            if failure:
                output = (result.output or "") + "\nkernel check failed: " + failure
                return lit.Test.Result(lit.Test.FAIL, output)
        return result

    def _syntax_error(self, kernel, passed_dir):
        # Plain clang, as a user inspecting the kernel runs it: the kernel tests
        # __OPENCL_C_VERSION__, which clang defines (issue 19 point 7).
        cmd = [self.clang, "-x", "cl", "-cl-std=CL1.2", "-fsyntax-only", kernel]
        digest = hashlib.sha256(" ".join(cmd[:-1]).encode())
        with open(kernel, "rb") as f:
            digest.update(f.read())
        passed = os.path.join(passed_dir, digest.hexdigest())
        if os.path.exists(passed):
            return None
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if p.returncode == 0:
            os.makedirs(passed_dir, exist_ok=True)
            open(passed, "w").close()
            return None
        return " ".join(cmd) + "\n" + p.stdout


def _kernels_under(path):
    if os.path.isfile(path):
        return [path] if _is_kernel(path) else []
    found = []
    for root, _, files in os.walk(path):
        found += [os.path.join(root, f) for f in sorted(files) if _is_kernel(f)]
    return found


def _is_kernel(name):
    base = os.path.basename(name)
    return base.startswith("proctex") and base.endswith(".cl")
