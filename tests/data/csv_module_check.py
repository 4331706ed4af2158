"""Reads a CSV file with Python's csv module (an RFC 4180 reader independent
of CsvTable, strict: malformed quoting is an error) and writes what it parsed
twice: every cell hex-encoded as x<hex>, one record per line, to CELLS; and the
records written back by csv.writer (CRLF line ends, every cell quoted) to COPY.

Usage: python3 csv_module_check.py IN.csv CELLS COPY
"""
import csv
import sys

source, cells, copy = sys.argv[1:]
with open(source, newline="", encoding="utf-8") as f:
    records = list(csv.reader(f, strict=True))
with open(cells, "w", encoding="ascii") as f:
    for record in records:
        f.write(" ".join("x" + cell.encode("utf-8").hex() for cell in record) + "\n")
with open(copy, "w", newline="", encoding="utf-8") as f:
    csv.writer(f, quoting=csv.QUOTE_ALL).writerows(records)
