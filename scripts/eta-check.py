#!/usr/bin/env python3
import re,sys
# The quality of the time left that `compare` prints: each log line's "about X left" against
# the time that was really left (the run's total in seconds minus the line's elapsed time).
# Usage: eta-check.py STDERR_LOG TOTAL_SECONDS (docs/report.md)
def dur(t):
    t=t.strip()
    m=re.match(r'(\d+) h (\d+) min',t)
    if m: return int(m[1])*3600+int(m[2])*60
    m=re.match(r'(\d+) min (\d+) s',t)
    if m: return int(m[1])*60+int(m[2])
    m=re.match(r'([\d.]+) s',t)
    return float(m[1])
lines=open(sys.argv[1]).read().splitlines()
total=float(sys.argv[2])
rows=[]
for l in lines:
    m=re.search(r'%\s+(.+?), about (.+) left',l)
    if not m: continue
    el=dur(m[1]); left=dur(m[2])
    rows.append((el,left,total-el))
worst=0
for el,left,true in rows:
    if el>=60 and true>0:
        r=left/true
        worst=max(worst,max(r,1/r))
print("lines",len(rows),"worst ratio from 60 s:",round(worst,2))
for el,left,true in rows[::max(1,len(rows)//12)]:
    print(f"{el:7.0f} s elapsed: predicted {left:6.0f} s left, true {true:6.0f} s, ratio {left/true if true>0 else float('nan'):.2f}")
