# Independent derivation of L-Py's share/examples/ex_lsystem2.lpy:
# queries ?P answered by a 2D turtle (y, z) before each step, cut %.
import math
def interpret(s):
    st=[]; y=0.0; z=0.0; a=0.0  # heading angle from +z toward -y
    for m in s:
        n=m[0]
        if n=='F':
            y-=math.sin(math.radians(a)); z+=math.cos(math.radians(a))
        elif n=='+': a+=m[1]
        elif n=='-': a-=m[1]
        elif n=='[': st.append((y,z,a))
        elif n==']': y,z,a=st.pop()
        elif n=='?P': m[1:]=[0.0,y,z]
def step(s):
    out=[]
    for m in s:
        n=m[0]
        if n=='A': out+= [['['],['+',60],['B'],[']'],['['],['-',60],['B'],[']'],['F'],['?P',0,0,0],['A']]
        elif n=='B': out+= [['F'],['?P',0,0,0],['@O',0.2],['B']]
        elif n=='?P':
            x,y,z=m[1:]
            if 4*y*y+(z-10)**2>100:
                out+= [['['],['+',2*z],['F'],[']'],['['],['-',2*z],['F'],[']'],['%']]
        else: out.append(m)
    # cut: % removes itself and the rest of its branch
    res=[]; i=0
    while i<len(out):
        if out[i][0]=='%':
            d=0; i+=1
            while i<len(out):
                if out[i][0]=='[': d+=1
                elif out[i][0]==']':
                    if d==0: break
                    d-=1
                i+=1
            continue
        res.append(out[i]); i+=1
    return res
s=[['A']]
for _ in range(24):
    interpret(s); s=step(s)
print('segments', sum(1 for m in s if m[0]=='F'), 'spheres', sum(1 for m in s if m[0]=='@O'))
