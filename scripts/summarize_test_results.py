#!/usr/bin/python3
"""Counts test cases in catkin's JUnit XML results and prints 'N passed, N failed, N skipped'.

catkin_test_results counts a gtest file's cases twice (suite and suites), so count <testcase>s.
Exits 1 when any case failed or no case ran.
"""
import pathlib
import sys
import xml.etree.ElementTree as ET

root = pathlib.Path(sys.argv[1])
passed = failed = skipped = 0
for path in sorted(root.rglob("*.xml")):
    try:
        cases = list(ET.parse(path).getroot().iter("testcase"))
    except ET.ParseError as error:
        print(f"{path}: unreadable result ({error})")
        failed += 1
        continue
    for case in cases:
        if case.find("failure") is not None or case.find("error") is not None:
            failed += 1
            print(f"FAILED: {path.name}: {case.get('classname')}.{case.get('name')}")
        elif case.find("skipped") is not None or case.get("status") == "notrun":
            skipped += 1
        else:
            passed += 1
print(f"{passed} passed, {failed} failed, {skipped} skipped")
sys.exit(1 if failed or passed == 0 else 0)
