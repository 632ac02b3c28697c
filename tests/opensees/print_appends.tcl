# `print -file f -node 1` appended N times to one file, and the bytes the
# process writes meanwhile (/proc/<pid>/io's wchar, which counts every
# write(2)): an append costs what it writes when they grow as N, not N^2.
# One truss node, so the text has OpenSees's Coordinates, Disps and
# Velocities lines.   argv: the output directory, N.
set out [lindex $argv 0]
set n [lindex $argv 1]
proc bytes_written {} {
    set io [open /proc/[pid]/io r]
    set text [read $io]
    close $io
    regexp {wchar: (\d+)} $text -> bytes
    return $bytes
}
wipe
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 2.5 0.0
uniaxialMaterial Elastic 1 2.0e11
element truss 1 1 2 0.01 1
set file [file join $out appends.txt]
set before [bytes_written]
for {set i 0} {$i < $n} {incr i} {
    print -file $file -node 1
}
set written [expr {[bytes_written] - $before}]
puts "appends $n written $written"
