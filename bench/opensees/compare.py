#!/usr/bin/env python3
"""poundfe and OpenSees 3.8 side by side on the same Tcl scripts.

    compare.py POUNDFE OPENSEES WORK_DIR [--write-reference REF_DIR] [--only CASE,...]
    compare.py POUNDFE --check REF_DIR WORK_DIR

First form: runs every case below in both programs (each in its own output
directory under WORK_DIR, the script's argv: that directory and the case's
words), times them, and prints for every recorder file the largest
difference over the history relative to the peak of its column, and the
ratio of the wall times. With --write-reference it also writes every 10th
row of OpenSees's files (and the last) to REF_DIR/CASE/FILE, the numbers the
test suite keeps (the binary and its sources stay outside the project).
Second form (the CLI test): runs poundfe only and compares its files with
those rows, with the tolerance of the case. Exit 1 naming the file and the
largest difference when one exceeds it."""
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "..", "..", "tests", "opensees")
# case: (script, argv words after the output directory, tolerance relative
# to the peak: round-off for linear models, 1e-6 for nonlinear ones)
CASES = {
    "column_force": ("fibre_column_cyclic.tcl", ["force"], 1e-6),
    "column_disp": ("fibre_column_cyclic.tcl", ["disp"], 1e-6),
    # committed-stiffness damping takes the members' tangent as it is: it
    # agrees once the P-Delta tangent is OpenSees's (measured 3e-12)
    "frame_record": ("fibre_frame_record.tcl", ["committed"], 1e-9),
    "frame_record_initial": ("fibre_frame_record.tcl", ["initial"], 1e-6),
    "sdof_linear": ("sdof_linear.tcl", [], 1e-10),
    "stick3_linear": ("stick3_linear.tcl", [], 1e-10),
    "portal_frame": ("portal_frame.tcl", [], 1e-10),
    "portal_pdelta": ("portal_pdelta.tcl", [], 1e-10),
    "cantilever_trig": ("cantilever_trig.tcl", [], 1e-10),
    "steel01_cyclic": ("steel01_cyclic.tcl", [], 1e-6),
    "pounding_ElasticPPGap": ("pounding_sticks.tcl", ["ElasticPPGap"], 1e-6),
    "pounding_ImpactMaterial": ("pounding_sticks.tcl", ["ImpactMaterial"], 1e-6),
    # HHT (alpha 0.8, 0.9) and NewtonLineSearch (a tolerance that makes it
    # search: 540 and 46 searches, eta 0.96 to 1.04)
    # element loads (eleLoad -beamUniform) on elastic members and on
    # dispBeamColumns of fibre sections, PDelta columns
    "portal_element_loads": ("portal_element_loads.tcl", [], 1e-9),
    "portal_element_loads_fibre": ("portal_element_loads.tcl", ["fibre"], 1e-9),
    # the same on forceBeamColumns (the sections carry s = b q + s_p):
    # gravity by element loads, loadConst, then the record
    "portal_element_loads_force": ("portal_element_loads.tcl", ["force"], 1e-9),
    # the same with the columns on section Aggregator (Elastic P, Steel01 Mz
    # that yields): a loaded member re-trials its sections at each step by
    # increments inside DBL_EPSILON, which Steel01 must take as no change
    "portal_element_loads_aggregator": ("portal_element_loads.tcl", ["aggregator"], 1e-9),
    # Steel01's dead band alone: a -1e-17 step on the hardening branch keeps
    # the hardening tangent, exposed by one Linear step of load
    "steel01_dead_band": ("steel01_dead_band.tcl", [], 1e-9),
    # the dead bands of Concrete01, Concrete02 (its last trial's stress and
    # tangent) and Steel02 (from the virgin state) in an RC fibre section:
    # curvature steps of 5e-16 at each peak, one Linear step of moment after
    # the first
    "dead_bands_section": ("dead_bands_section.tcl", [], 1e-9),
    # a force-based RC cantilever reversed by 4e-16 (two steps, each inside
    # the element's DBL_EPSILON band, together outside it) at each peak, one
    # Linear step of load after each: the increment is the one since the
    # element's last update, skipped or not (measured 1e-13)
    "force_reversals": ("force_reversals.tcl", [], 1e-9),
    # Hysteretic's dead band: a virgin step of 1e-17 and back to 0, and a
    # reversal of 1e-17 at each peak, each exposed by one Linear step of load
    # (measured 5e-19)
    "hysteretic_dead_band": ("hysteretic_dead_band.tcl", [], 1e-12),
    # failed steps reverted and retried: the elements updated at the
    # committed state, Hysteretic's tangent left as the failed trial made it
    # (the same failures and rows; measured 1.3e-13)
    "failed_step_retry": ("failed_step_retry.tcl", [], 1e-9),
    # the fibre frame of dispBeamColumns, damping on the committed stiffness:
    # its beams' fibres sit at strains of ~1e-20 after gravity, inside
    # Concrete01's band (their tangent E_c, not 0, enters K_c)
    "frame_record_disp": ("fibre_frame_record.tcl",
                          ["committed", "Newton", "Newmark 0.5 0.25", "disp"], 1e-9),
    "frame_hht": ("fibre_frame_record.tcl", ["committed", "Newton", "HHT 0.8"], 1e-9),
    "pounding_hht": ("pounding_sticks.tcl",
                     ["ImpactMaterial", "Newton", "NormDispIncr", "HHT 0.9"], 1e-9),
    "frame_line_search": ("fibre_frame_record.tcl",
                          ["initial", "NewtonLineSearch -tol 0.001"], 1e-9),
    "pounding_line_search": ("pounding_sticks.tcl",
                             ["ElasticPPGap", "NewtonLineSearch -tol 0.01 -pFlag 0"], 1e-9),
    # KrylovNewton (OpenSees's AcceleratedNewton with KrylovAccelerator):
    # the default subspace of 3 on the fibre frame, a subspace of 1 (a new
    # tangent every second iteration) with the energy test on the pounding pair
    "frame_krylov": ("fibre_frame_record.tcl", ["committed", "KrylovNewton"], 1e-9),
    "pounding_krylov": ("pounding_sticks.tcl",
                        ["ElasticPPGap", "KrylovNewton -maxDim 1", "EnergyIncr"], 1e-9),
    # BFGS (OpenSees's BFGS.cpp): the default 10 quasi-Newton increments a
    # tangent on the fibre frame; 3 on the pounding pair, whose inner test
    # then runs out and a new tangent follows (33 times)
    # RelativeNormDispIncr (|dx| over the step's first |dx|)
    "pounding_relative": ("pounding_sticks.tcl",
                          ["ImpactMaterial", "Newton", "RelativeNormDispIncr"], 1e-9),
    "frame_bfgs": ("fibre_frame_record.tcl", ["committed", "BFGS"], 1e-9),
    "pounding_bfgs": ("pounding_sticks.tcl", ["ImpactMaterial", "BFGS -count 3"], 1e-9),
    # sp in a Plain pattern (constraints Transformation): a fibre beam's end
    # rotation and deflection imposed past cracking and yield and back
    "beam_imposed": ("beam_imposed.tcl", [], 1e-6),
    # the rate-dependent contact materials and Viscous between the pounding
    # pair, with each gap material's stress, strain and tangent (OpenSees
    # 3.8's sign: Hertzdamp's and JankowskiImpact's tangents are negative),
    # under Newton: OpenSees 3.8 stops JankowskiImpact at 5.656 s and Viscous
    # (alpha 0.5) at 3.038 s, where the test is not met after 50 iterations,
    # and poundfe at the same steps with the same norms. JankowskiImpact's
    # tangent grows as delta^((n-3)/2) at the onset of a contact: 1e-8
    "pounding_Hertzdamp": ("pounding_sticks.tcl", ["Hertzdamp"], 1e-9),
    "pounding_JankowskiImpact": ("pounding_sticks.tcl", ["JankowskiImpact"], 1e-8),
    "pounding_ViscoelasticGap": ("pounding_sticks.tcl", ["ViscoelasticGap"], 1e-9),
    "pounding_Viscous": ("pounding_sticks.tcl", ["Viscous"], 1e-9),
    # Parallel (an ElasticPPGap and a ViscoelasticGap, factors 0.5: both stop
    # at 3.31 s under Newton; an ElasticPPGap and a Viscous, whose damping
    # tangent times its factor is the Parallel's, as OpenSees 3.8's
    # ParallelMaterial's, which zeroLength adds to its damping matrix) and
    # MinMax (an ImpactMaterial failing for good in its third impact)
    "pounding_Parallel": ("pounding_sticks.tcl", ["Parallel"], 1e-9),
    "pounding_ParallelViscous": ("pounding_sticks.tcl", ["ParallelViscous"], 1e-9),
    "pounding_MinMax": ("pounding_sticks.tcl", ["MinMax"], 1e-9),
    # ViscousDamper (its force integrated over the step by OpenSees's
    # adaptive Dormand-Prince, Adams-Bashforth-Moulton with a pin's play, and
    # Rosenbrock; tangent 0 as OpenSees's) and Series (a yielding link behind
    # an elastic brace; two yielding links with -iter)
    "pounding_ViscousDamper": ("pounding_sticks.tcl", ["ViscousDamper"], 1e-9),
    "pounding_ViscousDamperABM": ("pounding_sticks.tcl", ["ViscousDamperABM"], 1e-9),
    "pounding_ViscousDamperROS": ("pounding_sticks.tcl", ["ViscousDamperROS"], 1e-9),
    # Adams-Bashforth-Moulton at Alpha 0.3 at the onset of a steady
    # velocity, and the exact force (Dormand-Prince, tolerances 1e-12)
    "damper_onset_ABM": ("damper_onset.tcl", ["ABM"], 1e-9),
    "damper_onset_exact": ("damper_onset.tcl", ["exact"], 1e-9),
    "pounding_Series": ("pounding_sticks.tcl", ["Series"], 1e-9),
    "pounding_SeriesIter": ("pounding_sticks.tcl", ["SeriesIter"], 1e-9),
    # twoNodeLink: a bearing of three materials with -shearDist and -pDelta
    # under a 2D cantilever, a gap link between the tops; 3D sticks of
    # six-material links (-orient, -pDelta, -doRayleigh) and a diagonal gap.
    # Both agree to 4e-15 up to the first contact; each contact of the stiff
    # gap then multiplies round-off by about 100: OpenSees 3.8 against itself
    # with another solver (UmfPack for BandGeneral) differs by 3.1e-10 (2d)
    # and 5.8e-8 (3d), poundfe from OpenSees by 4.8e-10 and 3.9e-8
    "links_2d": ("two_node_links.tcl", ["2d"], 1e-8),
    "links_3d": ("two_node_links.tcl", ["3d"], 1e-6),
    # a 3D frame of elasticBeamColumns (PDelta columns, Linear beams, vecxz)
    # pounding a neighbour's column through a twoNodeLink gap, gravity then
    # the record along X and Y
    "frame_3d_elastic": ("elastic_frame_3d.tcl", [], 1e-9),
    # forceBeamColumn columns and dispBeamColumn beams on 3D fibre sections
    # (-GJ), gravity then two components
    "frame_3d_fibre": ("fibre_frame_3d.tcl", [], 1e-6),
    # the same with element loads in space (eleLoad -beamUniform Wy Wz Wx on
    # the forceBeamColumn columns and dispBeamColumn beams), and on members
    # of 3D Aggregator sections (P, Mz, My, T; Mz and My yield)
    "frame_3d_loads": ("fibre_frame_3d.tcl", ["loads"], 1e-6),
    "frame_3d_aggregator": ("fibre_frame_3d.tcl", ["aggregator"], 1e-9),
    # Rayleigh damping by region (-ele, -node, -eleOnly over a domain's
    # rayleigh) and twoNodeLink -mass with and without -doRayleigh, a gap
    # between two frames; then one rayleigh after the regions, which clears them
    "region_damping": ("region_damping.tcl", [], 1e-9),
    "region_damping_uniform": ("region_damping.tcl", ["uniform"], 1e-9),
    "region_damping_ranges": ("region_damping.tcl", ["ranges"], 1e-9),
    # ElasticPPGap with Fy > 0 and gap < 0: strain 0 is past the yield strain,
    # yet the virgin elastic range stays [gap, Fy/E + gap] (OpenSees 3.8's
    # constructor, with its warning on the alternate signs)
    "pounding_ElasticPPGapSigns": ("pounding_sticks.tcl", ["ElasticPPGapSigns"], 1e-9),
    # the ElasticPPGap under initial-stiffness damping (-doRayleigh 1): an
    # open gap's initial tangent is 0 (EPPGapMaterial::getInitialTangent)
    "pounding_ElasticPPGapK0": ("pounding_sticks.tcl", ["ElasticPPGapK0"], 1e-9),
    # truss -rho at the supports under a record: the bars' ground-motion
    # load enters the reactions (Truss::getResistingForce)
    "truss_mass": ("truss_mass.tcl", [], 1e-9),
    # OpenSees's BoucWen storey (its backward Euler and Newton for z from
    # 0.01), with and without Baber-Noori degradation
    "bouc_wen_storey": ("bouc_wen_storey.tcl", [], 1e-9),
    "bouc_wen_degrading": ("bouc_wen_storey.tcl", ["degrading"], 1e-9),
    # recorder Drift, EnvelopeNode and EnvelopeElement (with -time: the time
    # of each extreme), -dT as a multiple of the step and not, -rTolDt,
    # -timeSeries: a frame pounding a stick through an ElasticPPGap
    "recorder_kinds": ("recorder_kinds.tcl", [], 1e-9),
    # members' -mass under UniformExcitation: a 2D elasticBeamColumn takes
    # its ground-motion load twice (OpenSees 3.8's ElasticBeam2d), the
    # others once; the columns' load enters the reactions
    "beam_mass_elastic": ("beam_mass.tcl", ["elasticBeamColumn"], 1e-10),
    "beam_mass_force": ("beam_mass.tcl", ["forceBeamColumn"], 1e-10),
    "beam_mass_disp": ("beam_mass.tcl", ["dispBeamColumn"], 1e-10),
    "beam_mass_elastic_3d": ("beam_mass.tcl", ["elasticBeamColumn", "3d"], 1e-10),
    "beam_mass_force_3d": ("beam_mass.tcl", ["forceBeamColumn", "3d"], 1e-10),
    "beam_mass_disp_3d": ("beam_mass.tcl", ["dispBeamColumn", "3d"], 1e-10),
    # the same with -cMass (the consistent mass on every DOF of the
    # members' ends; 3D with the roof's rotations free): eigenvalues, history
    "beam_cmass_elastic": ("beam_mass.tcl", ["elasticBeamColumn", "2d", "-cMass"], 1e-10),
    "beam_cmass_disp": ("beam_mass.tcl", ["dispBeamColumn", "2d", "-cMass"], 1e-10),
    "beam_cmass_elastic_3d": ("beam_mass.tcl", ["elasticBeamColumn", "3d", "-cMass"], 1e-10),
    "beam_cmass_disp_3d": ("beam_mass.tcl", ["dispBeamColumn", "3d", "-cMass"], 1e-10),
    # reactions at nodes with their own mass under two ground components:
    # a fixed support and a roller with mass, free nodes with mass (each
    # node's ground-motion load -m a_g is in its unbalanced load)
    "node_mass_reactions": ("node_mass_reactions.tcl", [], 1e-10),
    # fixX, fixY -tol, the tags recorder returns, remove recorder, remove
    # recorders, remove loadPattern, testIter, testNorm (its norms to the
    # yielding stick's round-off: those below 1e-15 of the peak are noise),
    # getNP, getPID and getTime's six decimals
    "queries": ("queries.tcl", [], 1e-10),
    # zeroLengths added after an analyze to moved nodes, strains and rates
    # measured from that moment (ZeroLength's d0 and v0; measured 5e-15)
    "zero_length_late": ("zero_length_late.tcl", [], 1e-9),
    # the same with a truss added (Truss's -useInitialDisp, OpenSees's default)
    "truss_late": ("zero_length_late.tcl", ["truss"], 1e-9),
    # ArcLength past the limit point of a shallow arch of corotational
    # beams, down its unstable branch to the second limit point and, as
    # OpenSees's sign of the last step's load increment takes it, back
    "arc_length_arch": ("arc_length_arch.tcl", [], 1e-9),
    # a 3D storey with rigidDiaphragm, equalDOF and rigidLink bar under
    # constraints Lagrange (poundfe: Transformation's displacements, which
    # meet the constraints as exactly; measured 9e-15) and Penalty 1e13 1e13
    # (measured 2.5e-10: the penalty's condition number times round-off; its
    # own error, Penalty against Lagrange, is 3.6e-4)
    "handlers_lagrange": ("constraint_handlers.tcl", ["Lagrange"], 1e-10),
    "handlers_penalty": ("constraint_handlers.tcl", ["Penalty", "1.0e13", "1.0e13"], 1e-9),
    # the same with 5 t in the plane at each corner of the diaphragm, which
    # only Penalty takes (measured 7.8e-11; 2.0 times the peak from the
    # case without them)
    "handlers_penalty_mass": ("constraint_handlers.tcl",
                              ["-cornerMass", "5000.0", "Penalty", "1.0e13", "1.0e13"], 1e-9),
    # halfway through the record a corner leaves the diaphragm and the
    # neighbour's top its equalDOF (`remove mp`)
    "handlers_release": ("constraint_handlers.tcl", ["-release", "Lagrange"], 1e-10),
    # reset halfway through a record (a yielded brace, time 0, an
    # EnvelopeNode's extremes), reactions -dynamic and -rayleigh, and the
    # force of members with mass under a record (with their ground-motion
    # load: twice for a 2D elasticBeamColumn, once for a truss -rho)
    "domain_commands": ("domain_commands.tcl", [], 1e-9),
    # RelativeNormDispIncr under NewtonLineSearch, whose own copy of the
    # test, started afresh at each iteration, measures a ratio of 1 and so
    # always searches, at the last iteration on a residual of round-off
    # (whose etas differ between the programs: no -pFlag 0 here)
    "pounding_relative_line_search": ("pounding_sticks.tcl",
                                      ["ImpactMaterial", "NewtonLineSearch -tol 0.01",
                                       "RelativeNormDispIncr"], 1e-9),
    # analysis VariableTransient (6 steps fail and are tried again shorter,
    # 16 step lengths) under a record of uneven times: Path -time -values,
    # and -fileTime -filePath; a Path -dt with -startTime, -prependZero and
    # -useLast
    "variable_steps": ("variable_steps.tcl", [], 1e-9),
    "variable_steps_files": ("variable_steps.tcl", ["files"], 1e-9),
    # remove element (a yielded link, a spring), node (its anchor), sp (a
    # fixity: the mass then swings) and timeSeries mid-record
    "remove_objects": ("remove_objects.tcl", [], 1e-9),
    # zeroLengthSection hinges (Fiber, Aggregator, Elastic; -orient,
    # -doRayleigh 0) under elastic columns, in the plane and in space
    # (measured 3e-15 and 8e-15)
    "zls_2d": ("zero_length_section.tcl", ["2d"], 1e-9),
    "zls_3d": ("zero_length_section.tcl", ["3d"], 1e-9),
    # corotTruss: a shallow truss pushed through its snap-through (the same
    # bits), a yielding tripod under two components (measured 1.6e-12)
    "corot_2d": ("corot_truss.tcl", ["2d"], 1e-9),
    "corot_3d": ("corot_truss.tcl", ["3d"], 1e-9),
    # modalDamping on a yielding three-storey frame: OpenSees's BandGeneral
    # keeps only the modal damping matrix's entries inside the band in its
    # tangent, so Newton's path differs (2.3e-9; with FullGeneral the two
    # agree to 2.6e-14); modalDampingQ (the force alone) agrees to 4.7e-14
    "modal_one": ("modal_damping.tcl", ["one"], 1e-8),
    "modal_each": ("modal_damping.tcl", ["each"], 1e-8),
    "modal_fewer": ("modal_damping.tcl", ["fewer"], 1e-8),
    "modal_quasi": ("modal_damping.tcl", ["quasi"], 1e-12),
    # the same under HHT 0.8 with FullGeneral in both: the modal force at
    # HHT's velocity at t + dt, no modal matrix in HHT's tangent
    "modal_hht": ("modal_damping.tcl", ["hht"], 1e-12),
    "modal_hht_quasi": ("modal_damping.tcl", ["hht_quasi"], 1e-12),
    # the roof's mass doubled after `eigen`: M phi kept from `eigen`
    "modal_mass": ("modal_damping.tcl", ["mass"], 1e-12),
    "modal_rayleigh": ("modal_damping.tcl", ["rayleigh"], 1e-8),
    # -cMass 1 on truss and corotTruss: eigenvalues, a yielding truss's
    # history and reactions (measured 3.2e-14), a yielding tripod (9.6e-13)
    "cmass_truss": ("consistent_mass.tcl", ["truss"], 1e-9),
    "cmass_corot": ("consistent_mass.tcl", ["corot"], 1e-9),
    # rigidLink beam (2D and 3D, offsets along every axis) under each
    # handler, gravity then a record, `remove mp` halfway (Lagrange:
    # algorithm Linear, as OpenSees's NormDispIncr counts its multipliers)
    "rigid_beam_2d": ("rigid_beam.tcl", ["2d"], 1e-10),
    "rigid_beam_2d_lagrange": ("rigid_beam.tcl", ["2d", "Lagrange"], 1e-10),
    "rigid_beam_2d_penalty": ("rigid_beam.tcl", ["2d", "Penalty", "1.0e12", "1.0e12"], 1e-9),
    "rigid_beam_3d": ("rigid_beam.tcl", ["3d"], 1e-10),
    "rigid_beam_3d_lagrange": ("rigid_beam.tcl", ["3d", "Lagrange"], 1e-10),
    "rigid_beam_3d_penalty": ("rigid_beam.tcl", ["3d", "Penalty", "1.0e12", "1.0e12"], 1e-9),
    # chains through rigid ties (an equalDOF retained by a rigidLink beam's or
    # a rigidDiaphragm's constrained node, links on such nodes, a link on a
    # link) under Lagrange, whose answer poundfe's Transformation gives too
    # (OpenSees 3.8's Transformation handler mis-maps these chains)
    "tie_chains_2d": ("tie_chains.tcl", ["2d", "Lagrange"], 1e-10),
    "tie_chains_3d": ("tie_chains.tcl", ["3d", "Lagrange"], 1e-10),
    "tie_chains_3d_penalty": ("tie_chains.tcl", ["3d", "Penalty", "1.0e12", "1.0e12"], 1e-9),
    # an elasticBeamColumn (PDelta) and a truss with -rho added on nodes
    # that have moved: measured from their displacements then
    "moved_nodes": ("moved_nodes.tcl", [], 1e-9),
    # fibre forceBeamColumn and dispBeamColumn members, an elasticBeamColumn
    # (2d: Corotational; 3d: PDelta) made on nodes that have moved, after
    # `remove element` and on a new apex: measured from their
    # displacements then
    "moved_members_2d": ("moved_members.tcl", ["2d"], 1e-9),
    "moved_members_3d": ("moved_members.tcl", ["3d"], 1e-9),
    # rayleigh before a gable is made (its node and member undamped), a
    # beam removed and made again (undamped), a region's factors on the
    # gable's member and nodes, and (2d) a truss -cMass on moved nodes
    "rayleigh_later_2d": ("rayleigh_later.tcl", ["2d"], 1e-9),
    "rayleigh_later_3d": ("rayleigh_later.tcl", ["3d"], 1e-9),
    # `reset` after a fibre forceBeamColumn was made on a moved node, then
    # the static stage again: the member's first update after the reset is
    # the linear one (initialFlag = 0) and Newton comes back to the state
    # before it
    "moved_member_reset_2d_linear": ("moved_member_reset.tcl", ["2d", "Linear"], 1e-9),
    "moved_member_reset_2d_pdelta": ("moved_member_reset.tcl", ["2d", "PDelta"], 1e-9),
    "moved_member_reset_2d_corotational": ("moved_member_reset.tcl", ["2d", "Corotational"], 1e-9),
    "moved_member_reset_3d_linear": ("moved_member_reset.tcl", ["3d", "Linear"], 1e-9),
    "moved_member_reset_3d_pdelta": ("moved_member_reset.tcl", ["3d", "PDelta"], 1e-9),
    # geomTransf Corotational in space (CorotCrdTransf3d: nodal triads turned
    # by the iterations' rotation increments, so the path of Newton's
    # iterates enters the state): a skew cantilever rolled into a circle; a
    # column under axial and biaxial loads and a torque pushed to a third of
    # its height, of each member type; a two-storey frame of fibre columns
    # (yielding) under two components
    "corot3d_circle": ("corotational_3d.tcl", ["circle"], 1e-6),
    "corot3d_column_elastic": ("corotational_3d.tcl", ["column", "elasticBeamColumn"], 1e-6),
    "corot3d_column_force": ("corotational_3d.tcl", ["column", "forceBeamColumn"], 1e-6),
    "corot3d_column_disp": ("corotational_3d.tcl", ["column", "dispBeamColumn"], 1e-6),
    "corot3d_frame": ("corotational_3d.tcl", ["frame"], 1e-6),
    # the same with columns of each kind and Rayleigh damping on the initial
    # stiffness (B^T k_b0 B at the current geometry: each step for
    # dispBeamColumn and elasticBeamColumn, the first for forceBeamColumn)
    "corot3d_frame_initial": ("corotational_3d.tcl", ["frame", "initial"], 1e-6),
    # eigen -fullGenLapack on a bent skew cantilever: the corotational
    # tangent is not symmetric there, so the generalized problem is solved
    # whole (as dggev); before the load it is symmetric
    "corot3d_modes_elastic": ("corotational_3d.tcl", ["modes", "elasticBeamColumn"], 1e-9),
    "corot3d_modes_force": ("corotational_3d.tcl", ["modes", "forceBeamColumn"], 1e-9),
    "corot3d_modes_disp": ("corotational_3d.tcl", ["modes", "dispBeamColumn"], 1e-9),
    # modalDamping on those modes under a record
    "corot3d_modal": ("corotational_3d.tcl", ["modes", "dispBeamColumn", "modal"], 1e-6),
}
# Each line search iteration a program prints (-pFlag 0), kept as a table
# "iteration eta |s/s0|" in SEARCH_FILE: both print 6 significant digits,
# so that file is held to SEARCH_TOLERANCE of its peak.
SEARCH_LINE = re.compile(r"Line Search - iteration: (\d+) , eta\(j\) : (\S+) , "
                         r"Ratio \|sj/s0\| = (\S+)")
SEARCH_FILE, SEARCH_TOLERANCE = "line_search.out", 1e-5


def tolerance_of(case, name):
    return max(CASES[case][2], SEARCH_TOLERANCE if name == SEARCH_FILE else 0)


def run(program, case, out):
    script, words, _ = CASES[case]
    os.makedirs(out, exist_ok=True)
    start = time.perf_counter()
    cmd = [program] + (["opensees"] if program.endswith("poundfe") else [])
    done = subprocess.run(cmd + [os.path.join(CORPUS, script), out] + words,
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{program} {script} {words}: exit {done.returncode}\n{done.stderr[-2000:]}")
    searches = SEARCH_LINE.findall(done.stdout + done.stderr)
    if searches:
        with open(os.path.join(out, SEARCH_FILE), "w") as f:
            f.writelines(" ".join(row) + "\n" for row in searches)
    return time.perf_counter() - start


def peaks(table):
    """Each column's peak; a column below 1e-9 of the file's largest peak
    (an end moment or force zero but for round-off, such as a cantilever's
    free-end moment) is held to the file's largest peak instead."""
    peak = np.abs(table).max(axis=0)
    largest_peak = max(peak.max(), 1e-300)
    return np.where(peak < 1e-9 * largest_peak, largest_peak, peak)


def difference(a, b):
    """The largest difference of a's columns from b's relative to b's peaks."""
    if a.shape != b.shape:
        return float("inf")
    return float((np.abs(a - b).max(axis=0) / peaks(b)).max())


def largest(ours, theirs):
    """The largest difference of each column relative to its peak, at most."""
    return difference(np.loadtxt(ours, ndmin=2), np.loadtxt(theirs, ndmin=2))


def rows_kept(table):
    if len(table) <= 3:  # an Envelope recorder's rows: min, max, max |.|
        return table
    keep = list(range(0, len(table), 10))
    if keep[-1] != len(table) - 1:
        keep.append(len(table) - 1)
    return table[keep]


def side_by_side(poundfe, opensees, work, reference, only=None):
    failed = False
    print("| case | file | largest difference / peak | poundfe s | OpenSees s |")
    for case in only or CASES:
        mine, theirs = os.path.join(work, case, "poundfe"), os.path.join(work, case, "opensees")
        t_mine, t_theirs = run(poundfe, case, mine), run(opensees, case, theirs)
        for name in sorted(os.listdir(theirs)):
            d = largest(os.path.join(mine, name), os.path.join(theirs, name))
            failed |= d > tolerance_of(case, name)
            print(f"| {case} | {name} | {d:.1e} | {t_mine:.2f} | {t_theirs:.2f} |")
            if reference:
                os.makedirs(os.path.join(reference, case), exist_ok=True)
                np.savetxt(os.path.join(reference, case, name),
                           rows_kept(np.loadtxt(os.path.join(theirs, name), ndmin=2)), fmt="%.12g")
    return failed


def check(poundfe, reference, work):
    failed = False
    for case in sorted(os.listdir(reference)):
        mine = os.path.join(work, case)
        run(poundfe, case, mine)
        for name in sorted(os.listdir(os.path.join(reference, case))):
            kept = np.loadtxt(os.path.join(reference, case, name), ndmin=2)
            ours = rows_kept(np.loadtxt(os.path.join(mine, name), ndmin=2))
            d = difference(ours, kept)
            ok = d <= max(tolerance_of(case, name), 1e-11)  # the kept rows have 12 digits
            failed |= not ok
            print(f"{'ok  ' if ok else 'FAIL'} {case}/{name}: {d:.1e}")
    return failed


if __name__ == "__main__":
    if len(sys.argv) >= 5 and sys.argv[2] == "--check":
        sys.exit(1 if check(sys.argv[1], sys.argv[3], sys.argv[4]) else 0)
    args, only = sys.argv, None
    if "--only" in args:  # --only CASE[,CASE...]: those cases alone
        i = args.index("--only")
        only, args = args[i + 1].split(","), args[:i] + args[i + 2:]
    if len(args) not in (4, 6):
        sys.exit(__doc__)
    ref = args[5] if len(args) == 6 and args[4] == "--write-reference" else None
    sys.exit(1 if side_by_side(args[1], args[2], args[3], ref, only) else 0)
