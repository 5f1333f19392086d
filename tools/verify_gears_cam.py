#!/usr/bin/env python3
# Independent re-computation (textbook formulas, brute-force friction-sense search for the cam
# follower) of the gears/cam example decks, compared with their CSV output.
# Usage: tools/verify_gears_cam.py DIR   (DIR holds gears_reducer.csv ... cam_flat.csv)

import csv, math, sys
DIR = sys.argv[1] if len(sys.argv) > 1 else "data/expected"
class _np:
    class linalg:
        class LinAlgError(Exception): pass
        @staticmethod
        def solve(A,b):
            def det(M): return (M[0][0]*(M[1][1]*M[2][2]-M[1][2]*M[2][1])-M[0][1]*(M[1][0]*M[2][2]-M[1][2]*M[2][0])
                                +M[0][2]*(M[1][0]*M[2][1]-M[1][1]*M[2][0]))
            d=det(A)
            if abs(d)<1e-14: raise _np.linalg.LinAlgError()
            out=[]
            for j in range(3):
                M=[list(r) for r in A]
                for i in range(3): M[i][j]=b[i]
                out.append(det(M)/d)
            return out
    @staticmethod
    def array(x):
        return V(x) if not isinstance(x[0],list) else [list(r) for r in x]
    @staticmethod
    def hypot(a,b): return math.hypot(a,b)
    @staticmethod
    def sign(x): return (x>0)-(x<0)
class V(list):
    def __add__(s,o): return V([a+b for a,b in zip(s,o)])
    def __sub__(s,o): return V([a-b for a,b in zip(s,o)])
    def __neg__(s): return V([-a for a in s])
    def __rmul__(s,k): return V([k*a for a in s])
    def __mul__(s,k): return V([k*a for a in s])
np=_np
D=math.radians
def rd(p): return list(csv.DictReader(open(p)))
N_CMP=[0]
def close(a,b,name,rt=1e-9,at=1e-7):
    N_CMP[0]+=1
    if abs(a-b) > at + rt*abs(b): print("MISMATCH",name,a,b); return 1
    return 0
bad=0
def ang(v):
    if abs(v[0])<1e-9 and abs(v[1])<1e-9: return 0.0
    a=math.degrees(math.atan2(v[1],v[0])); return a+360 if a<0 else a
def angdiff(a,b): d=(a-b)%360; return min(d,360-d)
# reducer: lines of action. stage1: O1=(0,0), pitch point on x axis; force on gear 1 from gear 2
# is along the line of action at alpha to the common tangent, magnitude M1/(r1 cos a).
r=rd(DIR+'/gears_reducer.csv')
M1=50; r1=0.03; a=D(20)
F=M1/(r1*math.cos(a))
# CCW torque on gear 1 -> tooth force on gear 1 from gear 2 points -y (tangential) and -x (radial)
F12=np.array([-F*math.sin(a),-F*math.cos(a)])
bad+=close(float(r[0]['F12']),F,'F12')+close(float(r[0]['F12G']),ang(F12),'F12G')
M23=M1*40/20  # magnitude of torque on the intermediate shaft
e=np.array([math.cos(D(60)),math.sin(D(60))]); t=np.array([-e[1],e[0]])
r3=0.036; Ft3=M23/r3; Fr3=Ft3*math.tan(a)
# gear 2 turns CW, so gear 3 drives with a CW torque: the force on gear 3 from gear 4 gives CCW moment
F34=Ft3*t - Fr3*e
S=-(-F12+F34)
bad+=close(float(r[0]['FS2']),np.hypot(*S),'FS2')+close(float(r[0]['FS2G']),ang(S),'FS2G')
bad+=close(float(r[1]['M2']),M1*40*54/(20*18),'Mout')+close(float(r[1]['FS2G']),ang(F34),'FS4G')
# planetary: per-satellite numbers by the manual's formulas
p=rd(DIR+'/gears_planetary.csv')[0]
M1=120; dw1=0.06; k=3
bad+=close(float(p['F12']),2*M1/(dw1*k*math.cos(a)),'pl F12')
bad+=close(float(p['F2H']),2*(2*M1/(dw1*k)),'pl F2H')
bad+=close(float(p['M2']),M1*(1+72/24),'pl MH')+close(float(p['M3']),-M1*72/24,'pl M3')
bad+=close(float(p['F2HG']),0.0,'pl F2HG')
# bevel / spur / helical
b=rd(DIR+'/gears_bevel.csv')
Ft=2*80/0.07; d1=math.atan(20/40)
for row,(fr,fa,fn) in zip(b,[(Ft*math.tan(a)*math.cos(d1),Ft*math.tan(a)*math.sin(d1),Ft/math.cos(a)),
                            (Ft*math.tan(a),0,Ft/math.cos(a)),
                            (Ft*math.tan(a)/math.cos(D(12)),Ft*math.tan(D(12)),Ft/(math.cos(a)*math.cos(D(12))))]):
    bad+=close(float(row['Ft']),Ft,'Ft')+close(float(row['Fr1']),fr,'Fr')+close(float(row['Fa1']),fa,'Fa')+close(float(row['Fn']),fn,'Fn')
# cam: solve the follower by brute force (fsolve-like: try friction sign patterns, keep the consistent one)
def follower(theta,xb,mu,f2,v,l,aa,f):
    if f2<=0: return None
    c=np.array([math.sin(theta)+mu*math.cos(theta), math.cos(theta)-mu*math.sin(theta)])
    for sc in (-1,0,1):
        for sd in (-1,0,1):
            A=np.array([[c[0],1,1],[c[1],-v*f*sc,-v*f*sd],[xb*c[1]+aa*c[0],0,-l]])
            try: x=np.linalg.solve(A,[0,f2,0])
            except np.linalg.LinAlgError: continue
            if x[0]>0 and np.sign(round(x[1],9))==sc and np.sign(round(x[2],9))==sd: return x,c
    return 'jam'
for deck,rows,flat in [('cam_translating',rd(DIR+'/cam_translating.csv'),False),('cam_flat',rd(DIR+'/cam_flat.csv'),True)]:
    if flat: l,aa,f,mu=0.05,0.03,0.12,-0.1
    else: l,aa,f,mu=0.04,0.05,0.3,0.0
    for row in rows:
        th=D(float(row['theta'])); xb=float(row['xB']); f2=float(row['F2']); v=float(row['vdir'])
        res=follower(th,xb,mu,f2,v,l,aa,f)
        if res is None: bad+=close(float(row['LOST']),1,deck+' lost'); continue
        if res=='jam': bad+=close(float(row['JAM']),1,deck+' jam '+row['phi']); continue
        x,c=res; N=x[0]
        bad+=close(float(row['N']),N,deck+' N')
        bad+=close(float(row['F21']),N*np.hypot(*c),deck+' F21')
        bad+=close(float(row['F23C']),abs(x[1])*math.hypot(1,f if v!=0 else 0),deck+' F23C')
        bad+=close(float(row['F23D']),abs(x[2])*math.hypot(1,f if v!=0 else 0),deck+' F23D')
        bad+=close(float(row['KF']),N*np.hypot(*c)/f2,deck+' KF')
        bad+=close(float(row['KF2']),1.0 if N*np.hypot(*c)/f2>2 else 0.0,deck+' KF2')
print("mismatches:",bad,"of",N_CMP[0])
sys.exit(1 if bad else 0)
