# A reinforced-concrete rectangle as an OpenSees fibre section, shared by
# the fibre scripts: Concrete01 unconfined cover and confined core (Kent-
# Scott-Park), Steel02 bars (Menegotto-Pinto), units kN and m.
#   rc_section TAG B H COVER NBARS_PER_FACE BAR_AREA
# materials 1 (cover), 2 (core), 3 (steel) defined once by rc_materials.
proc rc_materials {} {
    uniaxialMaterial Concrete01 1 -30.0e3 -0.002 -6.0e3 -0.005
    uniaxialMaterial Concrete01 2 -39.0e3 -0.0026 -32.0e3 -0.02
    uniaxialMaterial Steel02 3 450.0e3 2.0e8 0.01 18.0 0.925 0.15
}
proc rc_section {tag b h cover nbars area} {
    set y1 [expr {$h/2.0}]; set z1 [expr {$b/2.0}]
    set yc [expr {$y1 - $cover}]; set zc [expr {$z1 - $cover}]
    section Fiber $tag {
        patch rect 2 10 1 [expr {-$yc}] [expr {-$zc}] $yc $zc
        patch rect 1 10 1 [expr {-$y1}] $zc $y1 $z1
        patch rect 1 10 1 [expr {-$y1}] [expr {-$z1}] $y1 [expr {-$zc}]
        patch rect 1 2 1 [expr {-$y1}] [expr {-$zc}] [expr {-$yc}] $zc
        patch rect 1 2 1 $yc [expr {-$zc}] $y1 $zc
        layer straight 3 $nbars $area $yc $zc $yc [expr {-$zc}]
        layer straight 3 $nbars $area [expr {-$yc}] $zc [expr {-$yc}] [expr {-$zc}]
        layer straight 3 2 $area 0.0 $zc 0.0 [expr {-$zc}]
    }
}
