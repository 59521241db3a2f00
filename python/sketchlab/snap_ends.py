"""snap_ends in Python: the example C++ corrector (examples/plugin/
snap_ends_plugin.cpp) written against the Python API; what the python
corrector plugin runs by default:

    corrector: {plugin: python, params: {module: sketchlab.snap_ends,
                                         class: SnapEnds, params: '{"radius": 0.02}'}}

Each stroke is fitted by the kernel's freehand fit (CASSIE app preprocessing),
then each end within radius/s of an existing curve moves onto its closest
point (dragging the Bézier tangent handle along; a line stays a line) and a
node joins the curves there. Same operations, same order as the C++ one, so
the sketches are identical to the bit.
"""
import sketchlab as sl


class SnapEnds:
    def __init__(self, radius=0.02):
        self.radius = radius
        self.preprocess = sl.cassie_app_preprocess()

    def correct(self, stroke, sketch):
        c = sl.Correction(sl.freehand_edit(stroke, sketch, self.preprocess))
        edit = c.edit
        added = edit.curves_added[0]
        curve = added.curve
        if curve.closed:
            return c
        network = sketch.network
        r = self.radius / stroke.workspace_scale
        cp = curve.control_points
        last = len(cp) - 1
        ends = [cp[0].copy(), cp[last].copy()]
        next_node = network.next_node_id()
        nodes, constraints, snapped = [], [], 0
        for e, (end, handle) in enumerate(((0, 1), (last, last - 1))):
            hits = network.curves_near(ends[e], r)
            if not hits:
                continue
            hit = hits[0]
            offset = hit.point - ends[e]
            ends[e] = hit.point
            if curve.kind == sl.CurveKind.bezier:
                cp[end] += offset
                cp[handle] += offset
            t = 0.0 if e == 0 else curve.t_max
            nodes.append(sl.Node(next_node, hit.point,
                                 [sl.NodeIncidence(added.id, t), sl.NodeIncidence(hit.curve, hit.t)]))
            next_node += 1
            k = sl.Constraint()
            k.kind = sl.ConstraintKind.point_on_curve
            k.references = [sl.ConstraintRef(sl.RefKind.stroke, stroke.id, float(e)),
                            sl.ConstraintRef(sl.RefKind.curve, hit.curve, hit.t)]
            k.target = hit.point
            k.hard = True
            k.enforced = True
            constraints.append(k)
            snapped += 1
        if snapped and curve.kind == sl.CurveKind.line:
            curve = sl.make_line(ends[0], ends[1])
        else:
            curve.control_points = cp
        added.curve = curve
        added.keypoints = sl.default_keypoints(curve)
        edit.curves_added = [added]
        edit.nodes_added = nodes
        c.edit = edit
        c.constraints = constraints
        c.stats.extra = {"ends_snapped": float(snapped)}
        return c
