#!/usr/bin/python3
"""Writes the small hand-made record samples used by the unit tests (blockdem issue 3).

Every sample holds the same 12 values, a_k = (-1)^k (k + 1) / 1000 in the file's unit, k = 0..11,
so that a test knows what to expect without a sidecar: PGA = 0.012 units at k = 11.
The layouts imitate the header variants of real files (see docs/records.md); the values, events
and stations are invented. Run: /usr/bin/python3 tests/data/records/make_samples.py
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
N = 12
VALUES = [(-1) ** k * (k + 1) / 1000.0 for k in range(N)]


def write(name, text, newline="\n"):
    with open(os.path.join(HERE, name), "w", newline="") as f:
        f.write(text.replace("\n", newline))


def fortran_e(x):
    """'-.1200000E-01': E15.7 without the leading zero, as PE&A and NGA-West2 write."""
    mantissa, exponent = f"{x:.6E}".split("E")
    digits = mantissa.replace("-", "").replace(".", "")
    e = int(exponent) + 1
    return f"{'-' if x < 0 else ''}.{digits}E{e:+03d}".rjust(15)


def rows(fields, per_line, pad_to=0):
    out = []
    for i in range(0, len(fields), per_line):
        line = "".join(fields[i:i + per_line])
        out.append(line.ljust(pad_to) if pad_to else line)
    return "\n".join(out) + "\n"


def at2_samples():
    e = [fortran_e(v) for v in VALUES]
    write("legacy_pea.AT2",
          "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\n"
          "TEST VALLEY 1/2/03 0405, SAMPLE ARRAY #1, 090 (TEST STATION 1)\n"
          "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.1 Hz LP=25.0 Hz\n"
          "NPTS=    12, DT= .01000 SEC\n" + rows(e, 5))
    write("nga_west2.AT2",
          "PEER NGA STRONG MOTION DATABASE RECORD\n"
          "Sample Event-01, 1/2/2003, Sample Station - Hill Top, 45\n"
          "ACCELERATION TIME SERIES IN UNITS OF G\n"
          + "NPTS=     12, DT=   .0050 SEC,".ljust(80) + "\n" + rows(e, 5, 80))
    west1 = [f"{v:15.6E}" for v in VALUES]  # NGA-West1 writes a leading 0: "   0.100000E-02"
    write("nga_west1.AT2",
          "PEER NGA STRONG MOTION DATABASE RECORD\n"
          "SAMPLE 01/02/03 0405, SAMPLE-STATION, 000 (AGENCY)\n"
          "ACCELERATION TIME HISTORY IN UNITS OF G\n"
          "12    0.0200    NPTS, DT\n" + rows(west1, 5))
    write("nga_filter.AT2",
          "PEER NGA STRONG MOTION DATABASE RECORD\n"
          "Sample-02, 1/2/2003, Pump Station, UP\n"
          "ACCELERATION TIME SERIES IN UNITS OF G\n"
          "NPTS=     12, DT=   .0100 SEC,   0 POLE @    30.00000 HZ,  -5 POLE @      .05000\n" + rows(e, 5))
    write("lowercase_dt.AT2",
          "PEER STRONG MOTION DATABASE RECORD\n"
          "SAMPLE 1/2/03, SAMPLE STATION, 270\n"
          "ACCELERATION TIME HISTORY IN UNITS OF G\n"
          "NPTS=    12, dt=  .00244\n" + rows(e, 5))
    write("crcrlf.at2",
          "PACIFIC ENGINEERING AND ANALYSIS STRONG-MOTION DATA\n"
          "SAMPLE 01/02/03 0405, SAMPLE PARK, 360".ljust(80) + "\n"
          "ACCELERATION TIME HISTORY IN UNITS OF G".ljust(80) + "\n"
          "NPTS=    12, DT= .02000 SEC\n" + rows(e, 5).rstrip("\n"), newline="\r\r\n")
    write("long_header.AT2",
          "Sample fault-normal record, rotated and scaled for a test\n"
          "Generated for blockdem; no real event\n"
          "Sample 2003, Station X, FN\n"
          "ACCELERATION TIME HISTORY IN UNITS OF G\n"
          "free text\n"
          "more free text\n"
          "12 0.0100 NPTS, DT\n" + rows(e, 5))


def knet_header(direction, rate, duration, scale):
    keys = [("Origin Time", "2003/01/02 04:05:00"), ("Lat.", "35.000"), ("Long.", "135.000"),
            ("Depth. (km)", "10"), ("Mag.", "5.5"), ("Station Code", "TST001"), ("Station Lat.", "35.1"),
            ("Station Long.", "135.1"), ("Station Height(m)", "12"), ("Record Time", "2003/01/02 04:05:20"),
            ("Sampling Freq(Hz)", f"{rate}Hz"), ("Duration Time(s)", str(duration)), ("Dir.", direction),
            ("Scale Factor", scale), ("Max. Acc. (gal)", "0.000"), ("Last Correction", "2003/01/02 04:05:05"),
            ("Memo.", "SAMPLE written for blockdem tests; not NIED data")]
    return "".join(f"{k:<18}{v}\n" for k, v in keys)


def knet_samples():
    # 3920(gal)/6182761 per count; counts = offset + a / factor, a in gal = 100 * VALUES (so PGA 1.2 gal)
    factor = 3920.0 / 6182761.0
    counts = [round(5000 + 100.0 * v / factor) for v in VALUES]
    # duration 0.12 s is not an integer; use 100 Hz x 1 s would need 100 values, so use 12 Hz x 1 s
    body = rows([f"{c:8d} " for c in counts], 8)
    write("knet_sample.EW", knet_header("E-W", 12, 1, "3920(gal)/6182761") + body)
    write("kiknet_sample.EW2", knet_header("5", 12, 1, "7845(gal)/8223790") +
          rows([f"{round(-71742 + 100.0 * v / (7845.0 / 8223790.0)):8d} " for v in VALUES], 8))


def cosmos_sample():
    ints = [-999] * 100
    ints[0:4] = [2, 1, 4, 120]
    ints[53] = 90  # azimuth
    reals = [-999.0] * 100
    reals[61] = 10.0  # dt in ms
    reals[62] = 0.12
    reals[87] = 980.665
    text = ["Corrected acceleration    (Format v01.20 with 13 text lines)",
            "Record of Sample Earthquake of Thu Jan  2, 2003 04:05 UTC",
            "Hypocenter: 35.000 135.000 H= 10km Mw=5.5",
            "Origin: 2003/01/02 04:05:00    UTC",
            "Statn No: 00-000001 Code:XX-TST1     TEST  Sample Station, Nowhere",
            "Coords: 35.1 135.1  Site geology:",
            "Recorder: (see cmnt)      ( ? Chns of   3 at Sta) Sensor: (see comment)",
            "Rcrd start time: 2003/01/02 04:05:10.000 UTC (Q=5) RcrdId: (see comment)",
            "Sta Chan   ?:Other   (Rcrdr Chan  ?) Location:",
            "Raw record length = 0.120 sec, Uncor max = 100, at 0.110 sec.",
            "Processed: sample, Max =   1.200 cm/sec2 at   0.110 sec",
            "Record filtered below  0.10 Hz (periods over 10.0 secs), and above 25.0 Hz",
            "Values used when parameter or data value is unknown/unspecified:   -999, -999.00"]
    out = "\n".join(text) + "\n"
    out += " 100 Integer-header values follow on  10 lines, Format= (10I8)\n"
    out += rows([f"{i:8d}" for i in ints], 10)
    out += " 100 Real-header values follow on  20 lines, Format= (5F15.6)\n"
    out += rows([f"{r:15.6f}" for r in reals], 5)
    out += "   2 Comment line(s) follow, each starting with a \"|\":\n"
    out += "| RcrdId: XX.sample.XX.TST1.HNE.--\n| sample written for blockdem tests\n"
    out += "      12 acceleration pts, approx    0 secs, units=cm/sec2(04),Format=(5E15.6)\n"
    out += rows([f"{100.0 * v:15.6e}" for v in VALUES], 5)
    out += "End-of-data for ChanHNE acceleration\n"
    write("cosmos_sample.V2", out)


def plain_samples():
    write("two_columns.csv", "# sample record written for blockdem tests\n# station: nowhere\n"
          "time[s],acc[gal]\n" + "".join(f"{k * 0.01:.2f},{100 * v:.1f}\n" for k, v in enumerate(VALUES)))
    write("values_only.txt", rows([f"{v:10.5f}" for v in VALUES], 8) + "*** End Data ***\n")
    write("jma_sample.csv",
          "SITE CODE= TST SAMPLE written for blockdem tests,,\nLAT.=   35.0000,,\nLON.=  135.0000,,\n"
          "SAMPLING RATE= 100Hz,,\nUNIT  = gal(cm/s/s),,\nINITIAL TIME = 2003 01 02 04 05 10,,\nNS,EW,UD\n"
          + "".join(f"{100 * v:.3f},{-100 * v:.3f},{50 * v:.3f}\n" for v in VALUES), newline="\r\n")


if __name__ == "__main__":
    at2_samples()
    knet_samples()
    cosmos_sample()
    plain_samples()
