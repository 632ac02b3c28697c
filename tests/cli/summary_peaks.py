"""The peaks of a run's summary.json that the coarse-step tests compare
(coarse_steps.sh, coarse_contact.sh): each storey's peak drift ratio and
peak absolute floor acceleration, and each gap's peak force, by name."""


def peaks(summary):
    p = {}
    for b in summary["buildings"]:
        for st in b["storeys"]:
            p[f"{b['name']} storey {st['storey']} drift"] = st["peak_drift_ratio"]
            p[f"{b['name']} floor {st['storey']} acceleration"] = \
                st["peak_absolute_floor_acceleration_m_s2"]
    for g in summary["gaps"]:
        p[g["label"] + " peak force"] = g["peak_force_N"]
    return p
