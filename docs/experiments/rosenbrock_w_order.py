# The order of ROS3Pw and ROS34PW2 (Rang & Angermann 2005) when W is not
# the Jacobian: a damped pendulum integrated to t = 2 with W = 0, a random
# W and a diagonal W; prints the observed order between N = 32, 64, 128
# steps (against N = 8192) and the local order of the embedded estimate.
# Measured: ROS3Pw 2.00 at W = 0 (a W-method of order 2 only), ROS34PW2
# 3.03. Needs numpy: `python3 docs/experiments/rosenbrock_w_order.py`.
import numpy as np
g=0.43586652150845900
A=np.array([[0,0,0,0],[0.87173304301691801,0,0,0],[0.84457060015369423,-0.11299064236484185,0,0],[0,0,1,0]])
G=np.array([[0,0,0,0],[-0.87173304301691801,0,0,0],[-0.90338057013044082,0.054180672388095326,0,0],[0.24212380706095346,-1.2232505839045147,0.54526025533510214,0]])
b=np.array([0.24212380706095346,-1.2232505839045147,1.5452602553351020,0.43586652150845900])
bh=np.array([0.37810903145819369,-0.096042292212423178,0.5,0.2179332607542295])
def ros3pw():
    g=0.78867513459481287
    A=np.array([[0,0,0],[1.5773502691896257,0,0],[0.5,0,0]])
    G=np.array([[0,0,0],[-1.5773502691896257,0,0],[-0.67075317547305480,-0.17075317547305482,0]])
    b=np.array([0.10566243270259355,0.049038105676657971,0.84529946162074843])
    bh=np.array([-0.1786327949540818,1/3,0.84529946162074843])
    return g,A,G,b,bh
def f(y): return np.array([y[1], -np.sin(y[0]) - 0.3*y[1]*abs(y[1]) + 0.1*y[0]*y[1]])
def step(meth,y,h,W):
    g,A,G,b,bh=meth
    s=len(b); k=[]
    for i in range(s):
        arg=y+sum(A[i,j]*k[j] for j in range(i))
        sm=sum(G[i,j]*k[j] for j in range(i)) if i else 0*y
        rhs=h*f(arg)+h*W@sm
        k.append(np.linalg.solve(np.eye(2)-h*g*W, rhs))
    return y+sum(b[i]*k[i] for i in range(s)), y+sum(bh[i]*k[i] for i in range(s))
def run(meth,N,W):
    y=np.array([1.0,0.0]);h=2.0/N
    for _ in range(N): y,_=step(meth,y,h,W)
    return y
for name,meth in [("ros34pw2",(g,A,G,b,bh)),("ros3pw",ros3pw())]:
  for Wn,W in [("0",np.zeros((2,2))),("rand",np.array([[-3.0,0.5],[0.2,-7.0]])),("diag",np.diag([0,-20.0]))]:
    ref=run(meth,8192,W)
    errs=[np.linalg.norm(run(meth,N,W)-ref) for N in (32,64,128)]
    print(name,Wn,["%.2f"%np.log2(errs[i]/errs[i+1]) for i in range(2)])
    # embedded order: local error of bh
    le=[]
    for h in (0.1,0.05):
        y0=np.array([1.0,0.0]); y1,yh=step(meth,y0,h,W); le.append(np.linalg.norm(y1-yh))
    print("   est order", np.log2(le[0]/le[1]))
