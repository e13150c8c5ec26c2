import json,glob,csv,collections,math
rows={(r['mission'],int(r['robot'])):r for r in csv.DictReader(open('/tmp/fs/m2/robots.csv'))}
out=[]
for f in sorted(glob.glob('/tmp/diag/0*.json')):
    m=f.split('/')[-1][:-5]; d=json.load(open(f))
    for k,v in d.items():
        r=rows[(m,int(k))]
        l=v['last100']; win=v['win']
        bat=win.get('BatteryMonitor',0)>=0.5 and [s for s in v['sug'] if s[0][0]=='BatteryMonitor' and s[0][1]=='STOP' and s[1]>=0.5]
        rl=v['routesLast100']; mapf = rl>0 and v['routesThroughWall']/rl>=0.5
        wander = l['pathM']>=10 and l['net']<0.35*l['pathM']
        park=[]
        for o,x in v['others'].items():
            if not x['done'] or x['atStart']>0.3: continue
            c,n=x['routeNear']; nearf=v['near06'].get(o,0)
            if (n and c/n>=0.2) or nearf>=0.5: park.append(f"r{o}@({x['endPos'][0]},{x['endPos'][1]}) clr{x['clear']} routes{c}/{n} near{nearf}")
        yld=win.get('Yield',0)
        out.append(dict(m=m[:4]+' '+r['world'],r=k,outc=r['outcome'],ck=f"{r['checkpointsReached']}/{r['checkpointsTotal']}",bat=bool(bat),map=mapf,wander=wander,park=park,yld=yld,win=win,rt=f"{v['routesThroughWall']}/{rl}",path=l['pathM'],net=l['net'],stop=l['stoppedFrac'],minbat=r['minBattery']))
json.dump(out,open('/tmp/diag/cls.json','w'),indent=1)
for o in out: print(o['m'],'r'+o['r'],o['outc'][:9],o['ck'],'BAT' if o['bat'] else '','MAP' if o['map'] else '','WANDER' if o['wander'] else '','YLD%.2f'%o['yld'] if o['yld']>=0.05 else '',o['rt'],o['path'],o['net'],'stop',o['stop'],'|',';'.join(o['park']))
