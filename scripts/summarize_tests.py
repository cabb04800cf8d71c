"""Prints one closing line 'N passed, N failed, N skipped' from lit's xUnit XML output."""
import sys
import xml.etree.ElementTree as ET

tree = ET.parse(sys.argv[1])
passed = failed = skipped = 0
for case in tree.iter("testcase"):
    if case.find("failure") is not None or case.find("error") is not None:
        failed += 1
    elif case.find("skipped") is not None:
        skipped += 1
    else:
        passed += 1
print(f"{passed} passed, {failed} failed, {skipped} skipped")
sys.exit(1 if failed or passed == 0 else 0)
