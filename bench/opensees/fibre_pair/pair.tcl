# The fibre pair benchmark in OpenSees 3.8, the twin of bench/fibre-pair.prm
# (poundfe run), written by hand: two 10-storey, 3-bay RC frames side by
# side, A (6 m bays, 70 t floors, 0.5 x 0.5 m columns) and B (5 m bays, 35 t
# floors, 0.4 x 0.4 m columns), 0.3 x 0.55 m beams, storeys of 3.2 m.
# Members: forceBeamColumn on Lobatto 5 points (OpenSees's element iteration,
# 10 iterations, 1e-12), fibre sections of the same patches and layers
# (Concrete02 core and cover, Steel02 bars), columns on PDelta, beams
# Linear. Each floor's mass in equal shares at its 4 joints on ux and uy.
# Gravity (the joints' weight) by LoadControl in 10 steps, held by loadConst
# -time 0; then Rayleigh damping a0 M + a1 K_initial (a0 = 0.33, a1 = 0.0056),
# the record along X (a_g in m/s^2 at 0.005 s from t = 0), Newmark average
# acceleration at 0.005 s for 20 s, Newton with NormDispIncr 1e-10.
# A gap at every floor: zeroLength on ElasticPPGap (k = 1e9 N/m, gap 0.02 m,
# a yield force no impact reaches: the linear contact law F = k d) from A's
# rightmost joint to B's leftmost joint.
#   OpenSees pair.tcl OUTPUT_DIR RECORD_FILE
#   poundfe opensees pair.tcl OUTPUT_DIR RECORD_FILE
# Recorders in OUTPUT_DIR (time first, 12 digits), one line per step:
#   floor_disp.out   ux of every floor joint, A then B, floor by floor
#                    bottom up, joints left to right (poundfe's floor
#                    displacement is their mean per floor)
#   floor_accel.out  the same joints' relative acceleration (poundfe's
#                    floor acceleration: their mean plus a_g)
#   gap_force.out    each gap's force (floor 1 to 10; compression negative)
#   gap_strain.out   each gap's deformation u_B - u_A (material 1 strain)
#   member_force.out / member_deformation.out: every member's basicForce
#                    (N, MI, MJ) and basicDeformation (eps, thetaI, thetaJ),
#                    A then B, columns storey by storey, then beams
#                    (poundfe's hinges.csv: moment and rotation of end I)
# A model-only mode: a third word "gravity" stops after the gravity analysis.
set out [lindex $argv 0]
set record [lindex $argv 1]
wipe
model basic -ndm 2 -ndf 3

set n_storeys 10; set n_bays 3; set H 3.2; set g 9.81
set separation 0.02
# building: bay width, floor mass, column section tag
set bay(1) 6.0; set floor_mass(1) 7.0e4; set column_section(1) 1
set bay(2) 5.0; set floor_mass(2) 3.5e4; set column_section(2) 2
set x0(1) 0.0
set x0(2) [expr {$n_bays*$bay(1) + $separation}]

# joint (building b, level k, column line j): tag 1000 b + 10 k + j
proc joint {b k j} { return [expr {1000*$b + 10*$k + $j}] }

uniaxialMaterial Concrete02 1 -39e6 -0.0035 -31e6 -0.02 0.1 3.9e6 1.95e9 ;# core
uniaxialMaterial Concrete02 2 -30e6 -0.002 -6e6 -0.006 0.1 3e6 1.5e9    ;# cover
uniaxialMaterial Steel02 3 420e6 200e9 0.01 20 0.925 0.15               ;# bars
# An RC rectangle (depth h along y, width b, cover c to the bars' axis):
# the core in n fibres along y, the cover top and bottom in 2, at the sides
# in n; bars top, bottom and (if any) at mid-depth, each of area A.
proc rc_fibres {tag h b c n top bottom middle A} {
    set y1 [expr {$h/2.0}]; set z1 [expr {$b/2.0}]
    set yc [expr {$y1 - $c}]; set zc [expr {$z1 - $c}]
    section Fiber $tag {
        patch rect 1 $n 1 [expr {-$yc}] [expr {-$zc}] $yc $zc
        patch rect 2 2 1 $yc [expr {-$z1}] $y1 $z1
        patch rect 2 2 1 [expr {-$y1}] [expr {-$z1}] [expr {-$yc}] $z1
        patch rect 2 $n 1 [expr {-$yc}] $zc $yc $z1
        patch rect 2 $n 1 [expr {-$yc}] [expr {-$z1}] $yc [expr {-$zc}]
        layer straight 3 $top $A $yc [expr {-$zc}] $yc $zc
        layer straight 3 $bottom $A [expr {-$yc}] [expr {-$zc}] [expr {-$yc}] $zc
        if {$middle > 0} {
            layer straight 3 $middle $A 0.0 [expr {-$zc}] 0.0 $zc
        }
    }
}
rc_fibres 1 0.5 0.5 0.04 10 4 4 2 4.91e-4  ;# column50
rc_fibres 2 0.4 0.4 0.04 8 3 3 2 3.14e-4   ;# column40
rc_fibres 3 0.55 0.3 0.04 10 4 3 0 3.14e-4 ;# beam30x55
geomTransf PDelta 1
geomTransf Linear 2
beamIntegration Lobatto 1 1 5
beamIntegration Lobatto 2 2 5
beamIntegration Lobatto 3 3 5

set floor_joints {}
set base_joints {}
set columns {}
set beams {}
foreach b {1 2} {
    set m [expr {$floor_mass($b)/($n_bays + 1)}]
    for {set k 0} {$k <= $n_storeys} {incr k} {
        for {set j 0} {$j <= $n_bays} {incr j} {
            set x [expr {$x0($b) + $j*$bay($b)}]
            if {$k == 0} {
                node [joint $b $k $j] $x 0.0
                fix [joint $b $k $j] 1 1 1
                lappend base_joints [joint $b $k $j]
            } else {
                node [joint $b $k $j] $x [expr {$k*$H}] -mass $m $m 0.0
                lappend floor_joints [joint $b $k $j]
            }
        }
    }
    # columns: element 1000 b + 10 k + j (storey k, line j); beams: 1000 b +
    # 500 + 10 k + j (floor k, bay j + 1)
    for {set k 1} {$k <= $n_storeys} {incr k} {
        for {set j 0} {$j <= $n_bays} {incr j} {
            set e [expr {1000*$b + 10*$k + $j}]
            element forceBeamColumn $e [joint $b [expr {$k - 1}] $j] [joint $b $k $j] 1 $column_section($b)
            lappend columns $e
        }
    }
    for {set k 1} {$k <= $n_storeys} {incr k} {
        for {set j 0} {$j < $n_bays} {incr j} {
            set e [expr {1000*$b + 500 + 10*$k + $j}]
            element forceBeamColumn $e [joint $b $k $j] [joint $b $k [expr {$j + 1}]] 2 3
            lappend beams $e
        }
    }
}

# gaps at every floor: A's rightmost joint to B's leftmost
set gaps {}
for {set k 1} {$k <= $n_storeys} {incr k} {
    uniaxialMaterial ElasticPPGap [expr {100 + $k}] 1e9 -1e15 [expr {-$separation}]
    element zeroLength [expr {5000 + $k}] [joint 1 $k $n_bays] [joint 2 $k 0] -mat [expr {100 + $k}] -dir 1
    lappend gaps [expr {5000 + $k}]
}

# gravity: the joints' weight
timeSeries Linear 1
pattern Plain 1 1 {
    foreach b {1 2} {
        set weight [expr {$floor_mass($b)*$g/($n_bays + 1)}]
        for {set k 1} {$k <= $n_storeys} {incr k} {
            for {set j 0} {$j <= $n_bays} {incr j} {
                load [joint $b $k $j] 0.0 [expr {-$weight}] 0.0
            }
        }
    }
}
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
if {[analyze 10] != 0} {
    puts stderr "pair.tcl: the gravity analysis failed"
    exit 2
}
loadConst -time 0.0
wipeAnalysis
if {[lindex $argv 2] eq "gravity"} {
    puts "gravity: roof of A [nodeDisp [joint 1 $n_storeys 0] 2] m"
    exit 0
}

recorder Node -file $out/floor_disp.out -time -precision 12 -node {*}$floor_joints -dof 1 disp
recorder Node -file $out/floor_accel.out -time -precision 12 -node {*}$floor_joints -dof 1 accel
recorder Element -file $out/gap_force.out -time -precision 12 -ele {*}$gaps force
recorder Element -file $out/gap_strain.out -time -precision 12 -ele {*}$gaps material 1 strain
recorder Element -file $out/member_force.out -time -precision 12 -ele {*}$columns {*}$beams basicForce
recorder Element -file $out/member_deformation.out -time -precision 12 -ele {*}$columns {*}$beams basicDeformation

rayleigh 0.33 0.0 0.0056 0.0
timeSeries Path 2 -dt 0.005 -filePath $record
pattern UniformExcitation 2 1 -accel 2
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze 4000 0.005]
puts "pair: status $status roof of A [nodeDisp [joint 1 $n_storeys 0] 1] m"
wipe
exit [expr {$status == 0 ? 0 : 2}]
