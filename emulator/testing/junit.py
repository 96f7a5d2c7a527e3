"""JUnit XML (the schema CI services read): one testsuite, a testcase per test with a failure
(message and file:line) or skipped element, and the output lines while it ran as its system-out."""
from __future__ import annotations

import xml.etree.ElementTree as ET

from emulator.testing.results import FAILED, INCONCLUSIVE, PASSED, SKIPPED, Summary


def junit_xml(summary: Summary, suite_name: str = "dpemu") -> str:
    results = summary.results
    suite = ET.Element("testsuite", {
        "name": suite_name,
        "tests": str(len(results)),
        "failures": str(summary.count(FAILED)),
        "errors": "0",
        "skipped": str(summary.count(SKIPPED) + summary.count(INCONCLUSIVE)),
        "time": f"{sum(r.seconds for r in results):.3f}",
    })
    for r in results:
        namespace, _, name = r.id.partition(":")
        case = ET.SubElement(suite, "testcase", {"classname": namespace, "name": name, "file": r.path,
                                                 "time": f"{r.seconds:.3f}"})
        if r.line:
            case.set("line", str(r.line))
        if r.counts_as == FAILED:
            failure = ET.SubElement(case, "failure", {"message": r.message})
            failure.text = "\n".join([f"{r.where}: {r.message}", *r.details])
        elif r.status == INCONCLUSIVE:
            ET.SubElement(case, "skipped", {"message": f"inconclusive: {r.where}: {r.message}", "type": INCONCLUSIVE})
        elif r.status != PASSED:
            ET.SubElement(case, "skipped", {"message": f"{r.where}: {r.message}"})
        if r.log:
            ET.SubElement(case, "system-out").text = "\n".join(r.log)
    root = ET.Element("testsuites")
    root.append(suite)
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"
