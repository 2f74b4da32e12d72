import { dfgSplitSum } from '/work/wt/lab-accuracy/src/math/integrate.js';
import { DataUtils } from 'three';
const N=+process.argv[2]||32, nodes=+process.argv[3]||16, layout=process.argv[4]||'centre';
const terms={ndf:process.argv[5]||'ggx', visibility:process.argv[6]||'smithGGXCorrelated'};
const h=(x)=>DataUtils.fromHalfFloat(DataUtils.toHalfFloat(x));
// texel i holds coordinate x_i; layout 'centre': x=(i+.5)/N; 'edge': x=i/(N-1)
const P=+process.argv[7]||1, Q=+process.argv[8]||2;
const coord = layout==='centre' ? (i)=>(i+0.5)/N : (i)=>i/(N-1);
const muOf=(x)=>x**(1/P), aOf=(y)=>y**Q;
const t0=performance.now();
const tab=[]; for (let j=0;j<N;j++){ const r=coord(j); for(let i=0;i<N;i++){ const [s,b]=dfgSplitSum(muOf(coord(i)), aOf(r), terms, {nodes}); tab.push([h(s),h(b)]); } }
const ms=performance.now()-t0;
const texel = (x)=> layout==='centre' ? x*N-0.5 : x*(N-1);
const sample=(mu,a)=>{ let x=Math.min(Math.max(texel(mu**P),0),N-1), y=Math.min(Math.max(texel(a**(1/Q)),0),N-1); const i0=Math.min(Math.floor(x),N-2), j0=Math.min(Math.floor(y),N-2); const fx=x-i0, fy=y-j0; const g=(i,j)=>tab[j*N+i]; return [0,1].map(k=>(1-fy)*((1-fx)*g(i0,j0)[k]+fx*g(i0+1,j0)[k])+fy*((1-fx)*g(i0,j0+1)[k]+fx*g(i0+1,j0+1)[k])); };
let worst=0, where, rows=[];
const mus=[0.001,0.003,0.01,0.02,0.03,0.05,0.08,0.12,0.2,0.3,0.45,0.6,0.77,0.9,0.97,1];
const als=[0.01,0.02,0.04,0.07,0.1,0.15,0.25,0.4,0.6,0.8,1];
for (const a of als) for (const mu of mus) { const ref=dfgSplitSum(mu,a,terms,{nodes:48}); const got=sample(mu,a); const e=Math.max(Math.abs(ref[0]-got[0]),Math.abs(ref[1]-got[1])); rows.push([mu,a,e]); if(e>worst){worst=e;where=[mu,a];} }
console.log(N,nodes,layout,P,Q,JSON.stringify(terms),'build ms',ms.toFixed(0),'worst',worst.toExponential(2),where);
const bad=rows.filter(r=>r[2]>1e-3); console.log('over 1e-3:',bad.length, bad.slice(0,12).map(r=>r.map(x=>+x.toPrecision(2)).join('/')).join(' '));
