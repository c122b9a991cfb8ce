# Generates rpg_pair_gt.txt / rpg_pair_est.txt (python3 make_rpg_pair.py): the reference ellipse at 30 Hz for 10 s,
# and an estimate with a yaw + translation offset, random-walk drift, +-3 ms timestamp jitter and every 7th pose missing.
import math, random
random.seed(3)
def q_from(yaw,pitch,roll):
    cy,sy=math.cos(yaw/2),math.sin(yaw/2);cp,sp=math.cos(pitch/2),math.sin(pitch/2);cr,sr=math.cos(roll/2),math.sin(roll/2)
    return (sr*cp*cy-cr*sp*sy, cr*sp*cy+sr*cp*sy, cr*cp*sy-sr*sp*cy, cr*cp*cy+sr*sp*sy)
K=math.pi/10
with open('rpg_pair_gt.txt','w') as g, open('rpg_pair_est.txt','w') as e:
    g.write('# timestamp tx ty tz qx qy qz qw\n'); e.write('# timestamp tx ty tz qx qy qz qw\n')
    drift=[0,0,0]; dyaw=0
    for k in range(300):
        t=k/30
        x,y,z=15*math.cos(K*t)+5,20*math.sin(K*t)+5,math.sin(10*K*t)+5
        yaw,pitch,roll=K*t,0.2*math.sin(t),0.1*math.cos(t)
        q=q_from(yaw,pitch,roll)
        g.write('%d.%09d %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n'%((1000000000+k*33333333)//1000000000,(1000000000+k*33333333)%1000000000,x,y,z,*q))
        if k%7==3: continue  # missing estimates
        drift=[d+random.gauss(0,0.003) for d in drift]; dyaw+=random.gauss(0,0.001)
        a=0.7
        xe=math.cos(a)*x-math.sin(a)*y+2+drift[0]; ye=math.sin(a)*x+math.cos(a)*y-1+drift[1]; ze=z+drift[2]+0.3
        qe=q_from(yaw+a+dyaw,pitch+random.gauss(0,0.002),roll)
        te=1000000000+k*33333333+random.randint(-3000000,3000000)
        e.write('%d.%09d %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n'%(te//1000000000,te%1000000000,xe,ye,ze,*qe))
