#!/usr/bin/env python3
"""Independent cross-check of kinetostat's T.FTN (&sixbar) CSV (standard library only).

Kinematics by complex numbers (positions by circle intersection, transfer functions by the
spec's formulas), then all pair reactions and M1 from ONE 14x14 linear system of the five
links' equilibrium equations (Gaussian elimination) -- a different route from the program's
closed-form group-by-group chain. Prints the largest deviation relative to the step's
largest force (M1 relative to that force times l1).

usage: tools/sixbar_crosscheck.py CSV [--example] [--legacy]
  default:   data/sixbar.nml's data (g = 9.81, f5 = 7*1000, 6*0)
  --example: data/sixbar_example.nml's data (g = 10, f5 = 1000)
  --legacy:  the deck had legacy_eq2 = .true.
"""
import cmath, csv, math, sys
D2R = math.pi/180
def params(g=10.0, f5=1000.0):
    return dict(a=0.17,b=0.34,l1=0.1,lam2=4,lam_s2=0.5,lam3=3,lam_de=3,lam4=2,lam_s4=0.5,lam_e=2.5,
                omega1=100.0,m1=50,j1=20,m2=5,j2=0.01,m3=8,j3=0.2,m4=2,j4=0.007,m5=6,g=g,f5=f5)
def position(p, phi1, legacy=False):
    a,b,l1=p['a'],p['b'],p['l1']
    L=math.hypot(a,b); l2=p['lam2']*l1; l3=p['lam3']*l1; lde=p['lam_de']*l1; l4=p['lam4']*l1; e=p['lam_e']*l1
    beta=math.atan2(a,b)
    B=l1*cmath.exp(1j*phi1); D=complex(L,0)
    dB=B-D; d=abs(dB)
    cg=(l3*l3+d*d-l2*l2)/(2*l3*d)
    g_=math.acos(cg)
    phi3=cmath.phase(dB)-g_
    C=D+l3*cmath.exp(1j*phi3)
    phi2=cmath.phase(C-B)
    psi=phi3-beta
    yE=lde*math.sin(psi)
    s4=(e-yE)/l4
    phi4=math.asin(s4)
    xH=lde*math.cos(psi)+l4*math.cos(phi4)
    return dict(phi1=phi1,phi2=phi2,phi3=phi3,phi4=phi4,xH=xH,B=B,C=C,D=D,
                E2=lde*cmath.exp(1j*psi), H2=complex(xH,e), beta=beta, L=L)
def kin(p, phi1, legacy=False, h=1e-4):
    # transfer functions by formulas (spec) ; returns dict
    q=position(p,phi1)
    l1=p['l1']; lam2,lam3,lde,lam4=p['lam2'],p['lam3'],p['lam_de'],p['lam4']
    f1,f2,f3,f4=phi1,q['phi2'],q['phi3'],q['phi4']; psi=f3-q['beta']
    s32=math.sin(f3-f2)
    u21=math.sin(f1-f3)/(lam2*s32); u31=math.sin(f1-f2)/(lam3*s32)
    num2=(math.cos(f1-f2) if legacy else math.cos(f1-f3))+lam2*u21**2*math.cos(f3-f2)-lam3*u31**2
    e2=num2/(lam2*s32)
    e3=(math.cos(f1-f2)+lam2*u21**2-lam3*u31**2*math.cos(f3-f2))/(lam3*s32)
    u41=-lde*math.cos(psi)*u31/(lam4*math.cos(f4))
    e4=(lde*(math.sin(psi)*u31**2-math.cos(psi)*e3)+lam4*math.sin(f4)*u41**2)/(lam4*math.cos(f4))
    q.update(u21=u21,u31=u31,u41=u41,e2=e2,e3=e3,e4=e4)
    return q
def kin_fd(p, phi1, h=1e-4):
    # second-order central differences of positions, for points too
    qs=[position(p,phi1+k*h) for k in (-1,0,1)]
    def d1(key): return (qs[2][key]-qs[0][key])/(2*h)
    def d2(key): return (qs[2][key]-2*qs[1][key]+qs[0][key])/h**2
    return d1,d2,qs
def forces(p, phi1, legacy=False):
    q=kin(p,phi1,legacy)
    w2=p['omega1']**2; l1=p['l1']; l2=p['lam2']*l1; l4=p['lam4']*l1
    a,b=p['a'],p['b']; L=q['L']; beta=q['beta']
    # frame 2 -> frame 1 rotation by beta - pi about D
    r21=cmath.exp(1j*(beta-math.pi))
    to1=lambda z2: q['D']+r21*z2
    vto1=lambda v2: r21*v2
    # gravity in frame 0 = -i g ; frame1 = frame0 rotated by alpha
    alpha=math.atan2(b,a)
    gdir1=-1j*cmath.exp(-1j*alpha)
    B,C,D=q['B'],q['C'],q['D']; E=to1(q['E2']); H=to1(q['H2'])
    f1,f2,f3,f4=phi1,q['phi2'],q['phi3'],q['phi4']
    # accelerations (analogue*w2), frame 1 for all (complex)
    e1=cmath.exp(1j*f1); e2=cmath.exp(1j*f2); e3=cmath.exp(1j*f3)
    aB=l1*(-1)*e1
    aS2=aB+p['lam_s2']*l2*(1j*q['e2']-q['u21']**2)*e2
    # E in frame 2: lde e^{i psi}; accel analogue
    psi=f3-beta; lde=p['lam_de']*l1
    aE2=lde*(1j*q['e3']-q['u31']**2)*cmath.exp(1j*psi)
    e4c=cmath.exp(1j*f4)
    aS4_2=aE2+p['lam_s4']*l4*(1j*q['e4']-q['u41']**2)*e4c
    aH2=aE2+l4*(1j*q['e4']-q['u41']**2)*e4c
    S2=B+p['lam_s2']*(C-B); S4=to1(q['E2']+p['lam_s4']*l4*e4c)
    g=p['g']
    loads=[]  # (link, point, force, couple) in frame 1
    loads.append((1,0j,p['m1']*g*gdir1,0.0))
    loads.append((2,S2,p['m2']*g*gdir1-p['m2']*aS2*w2,-p['j2']*q['e2']*w2))
    loads.append((3,D,p['m3']*g*gdir1,-p['j3']*q['e3']*w2))
    loads.append((4,S4,p['m4']*g*gdir1-p['m4']*vto1(aS4_2)*w2,-p['j4']*q['e4']*w2))
    loads.append((5,H,p['m5']*g*gdir1-p['m5']*vto1(aH2)*w2+vto1(p['f5']),0.0))
    # unknowns: F16(2) F21(2) F32(2) F36(2) F43(2) F54(2) f56(1) M1(1) = 14 ; eqs 5 links x3 = 15
    # slider moment eq is trivial (all at H) -> drop it => 14 eqs
    # pairs: A:1-6, B:2-1, C:3-2, D:3-6, E:4-3, H:5-4, guide 5-6 (normal y2), M1 on 1
    n=14
    rows=[]; rhs=[]
    def addlink(link, point_ref, include_moment=True):
        # build equations: sum F = 0 (x,y), sum M about point_ref = 0
        cols=[[0.0]*n for _ in range(3)]
        def addforce(idx, pt, sign, dirs):
            # force = sign*(u0*dir0 + u1*dir1)
            for k,dv in enumerate(dirs):
                c=idx+k
                fx,fy=sign*dv.real, sign*dv.imag
                r=pt-point_ref
                cols[0][c]+=fx; cols[1][c]+=fy; cols[2][c]+=r.real*fy-r.imag*fx
        X=[1+0j,1j]
        if link==1:
            addforce(0,0j,1,X); addforce(2,B,-1,X); cols[2][13]+=1.0
        if link==2:
            addforce(2,B,1,X); addforce(4,C,-1,X)
        if link==3:
            addforce(4,C,1,X); addforce(6,D,1,X); addforce(8,E,-1,X)
        if link==4:
            addforce(8,E,1,X); addforce(10,H,-1,X)
        if link==5:
            addforce(10,H,1,X); addforce(12,H,1,[vto1(1j)])
        sf=0j; sm=0.0
        for (lk,pt,F,Mc) in loads:
            if lk==link:
                sf+=F; r=pt-point_ref; sm+=r.real*F.imag-r.imag*F.real+Mc
        rows.extend([cols[0],cols[1]]); rhs.extend([-sf.real,-sf.imag])
        if include_moment:
            rows.append(cols[2]); rhs.append(-sm)
    addlink(1,0j); addlink(2,B); addlink(3,D); addlink(4,E); addlink(5,H,False)
    # gaussian elimination with partial pivoting
    A=[r[:]+[rhs[i]] for i,r in enumerate(rows)]
    for c in range(n):
        piv=max(range(c,n),key=lambda r:abs(A[r][c])); A[c],A[piv]=A[piv],A[c]
        for r in range(n):
            if r!=c:
                fct=A[r][c]/A[c][c]
                for k in range(c,n+1): A[r][k]-=fct*A[c][k]
    x=[A[i][n]/A[i][i] for i in range(n)]
    F16=complex(x[0],x[1]); F21=complex(x[2],x[3]); F32=complex(x[4],x[5]); F36=complex(x[6],x[7])
    F43=complex(x[8],x[9]); F54=complex(x[10],x[11]); f56=x[12]; M1=x[13]
    rot12=cmath.exp(-1j*(beta-math.pi))
    res=dict(q=q,F16=F16,F21=F21,F32=F32,F36=F36,F43_2=rot12*F43,F45_2=-rot12*F54,F54_2=rot12*F54,f56=f56,M1=M1,
             aS2=aS2*w2,aS4_2=aS4_2*w2,aH2=aH2*w2)
    return res
def deg(z): return math.degrees(cmath.phase(z))
def compare(csvfile, p, f5s, legacy=False):
    rows=list(csv.DictReader(open(csvfile)))
    worst=0; where=None
    for row,f5 in zip(rows,f5s):
        phi1=float(row['phi1'])
        p['f5']=f5
        r=forces(p,phi1*D2R,legacy)
        exp={'F21':r['F21'],'F32':r['F32'],'F43':r['F43_2'],'F45':r['F45_2'],'F36':r['F36'],'F16':r['F16']}
        scale=max(abs(v) for v in exp.values())
        for k,z in exp.items():
            d=abs(abs(z)-float(row[k]))/scale
            if d>worst: worst,where=d,(phi1,k,abs(z),row[k])
            ang=math.degrees(cmath.phase(z)); da=abs((ang-float(row[k+'G'])+180)%360-180)
            if da>1e-9*180 and da>worst*180: print('angle',phi1,k,ang,row[k+'G'])
        d=abs(r['f56']-float(row['F56']))/scale
        if d>worst: worst,where=d,(phi1,'F56')
        d=abs(r['M1']-float(row['M1']))/(scale*p['l1'])
        if d>worst: worst,where=d,(phi1,'M1',r['M1'],row['M1'])
    return worst,where

def main():
    args = sys.argv[1:]
    if not args or args[0].startswith('-'):
        print(__doc__)
        sys.exit(1)
    legacy = '--legacy' in args
    if '--example' in args:
        p, f5s = params(g=10.0), [1000.0]
    else:
        p, f5s = params(g=9.81), [1000.0] * 7 + [0.0] * 6
    worst, where = compare(args[0], p, f5s, legacy)
    print('max deviation %.3e (relative to the step\'s largest force) at %s' % (worst, where))
    sys.exit(0 if worst < 1e-9 else 1)

if __name__ == '__main__':
    main()
