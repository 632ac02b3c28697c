# The three eigenvalues of a 3-storey shear stick, printed (the command
# table's row test runs it from the command line and from Python).
model basic -ndm 1 -ndf 1
node 0 0.0
fix 0 1
foreach i {1 2 3} {
    node $i 0.0 -mass 1.0e5
    uniaxialMaterial Elastic $i 2.0e8
    element zeroLength $i [expr {$i - 1}] $i -mat $i -dir 1
}
puts [eigen 3]
