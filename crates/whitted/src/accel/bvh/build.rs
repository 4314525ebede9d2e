//! Building the tree: nodes split where the binned SAH (`sah`) finds it cheapest, down
//! to leaves of `LEAF_MAX` (or `MAX_DEPTH` levels), a node of up to `LEAF_SAH_MAX` kept
//! whole where the SAH prefers a leaf; big subtrees in parallel (`build_tree`), to the
//! same tree on any thread count. The items' boxes and centres are f32 (`Item`: the
//! boxes already rounded outward as the wide nodes keep them).

use super::sah::{bin, sah, surface_area};
use super::{Item, Node, BINS, BLANK, LEAF_SAH_MAX, MAX_DEPTH, TRAVERSE_COST};
use glam::{Vec3, Vec3A};

/// Subtrees over more primitives than this are built in parallel (below it a task costs
/// more than it saves).
const PAR_MIN: usize = 8192;

/// Fills node `index` with the bounds of `items` (which start at `offset` in the final
/// primitive order) and splits it, recursively.
pub(super) fn build_node(
    nodes: &mut Vec<Node>,
    items: &mut [Item],
    offset: usize,
    index: usize,
    depth: usize,
    leaf_max: usize,
) {
    let Some(mid) = split(nodes, items, offset, index, depth, leaf_max) else {
        return;
    };
    let left = nodes.len();
    nodes.push(BLANK);
    nodes.push(BLANK);
    nodes[index].first = left as u32;
    nodes[index].count = 0;
    let (a, b) = items.split_at_mut(mid);
    build_node(nodes, a, offset, left, depth + 1, leaf_max);
    build_node(nodes, b, offset + mid, left + 1, depth + 1, leaf_max);
}

/// A subtree built apart: its nodes with the root at 0 and children's indices local to
/// the vector, or a split whose two halves were built in parallel.
enum Sub {
    Nodes(Vec<Node>),
    Split(Node, Box<(Sub, Sub)>),
}

/// The nodes of the tree over `items` (at least one), in the order `build_node` alone
/// would not give but always the same: subtrees of more than `PAR_MIN` primitives are
/// split in this thread and their halves built by rayon's `join`, which changes where
/// the work runs, never what it computes. So the tree is the same on any thread count.
pub(super) fn build_tree(items: &mut [Item], leaf_max: usize) -> Vec<Node> {
    let sub = build_sub(items, 0, 0, leaf_max);
    let mut nodes = vec![BLANK];
    place(&mut nodes, sub, 0);
    nodes
}

fn build_sub(items: &mut [Item], offset: usize, depth: usize, leaf_max: usize) -> Sub {
    let mut root = [BLANK];
    if items.len() <= PAR_MIN {
        let mut nodes = vec![BLANK];
        build_node(&mut nodes, items, offset, 0, depth, leaf_max);
        return Sub::Nodes(nodes);
    }
    let Some(mid) = split(&mut root, items, offset, 0, depth, leaf_max) else {
        return Sub::Nodes(root.to_vec());
    };
    let (a, b) = items.split_at_mut(mid);
    // In a pool (the renderer's, sized by --threads) the halves are built side by side;
    // outside one, in turn: rayon's global pool would start a thread per core regardless.
    let halves = if rayon::current_thread_index().is_some() {
        rayon::join(
            || build_sub(a, offset, depth + 1, leaf_max),
            || build_sub(b, offset + mid, depth + 1, leaf_max),
        )
    } else {
        (
            build_sub(a, offset, depth + 1, leaf_max),
            build_sub(b, offset + mid, depth + 1, leaf_max),
        )
    };
    Sub::Split(root[0], Box::new(halves))
}

/// Writes `sub` with its root at `nodes[slot]` and the rest appended.
fn place(nodes: &mut Vec<Node>, sub: Sub, slot: usize) {
    match sub {
        Sub::Nodes(local) => {
            // Local index i ≥ 1 lands at base + i − 1.
            let base = nodes.len();
            let at = |i: u32| (base + i as usize - 1) as u32;
            let fix = |mut n: Node| {
                if n.count == 0 {
                    n.first = at(n.first);
                }
                n
            };
            nodes[slot] = fix(local[0]);
            nodes.extend(local[1..].iter().map(|&n| fix(n)));
        }
        Sub::Split(mut root, halves) => {
            let left = nodes.len();
            nodes.push(BLANK);
            nodes.push(BLANK);
            root.first = left as u32;
            root.count = 0;
            nodes[slot] = root;
            let (a, b) = *halves;
            place(nodes, a, left);
            place(nodes, b, left + 1);
        }
    }
}

/// Fills node `index` with the bounds of `items` and, unless it stays a leaf (which it
/// then also fills), partitions the items and says how many go left.
fn split(
    nodes: &mut [Node],
    items: &mut [Item],
    offset: usize,
    index: usize,
    depth: usize,
    leaf_max: usize,
) -> Option<usize> {
    let (mut lo, mut hi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
    let (mut clo, mut chi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
    for it in items.iter() {
        lo = lo.min(it.lo);
        hi = hi.max(it.hi);
        clo = clo.min(it.centre.into());
        chi = chi.max(it.centre.into());
    }
    let (clo, chi) = (Vec3::from(clo), Vec3::from(chi));
    nodes[index].b = [lo.as_dvec3().to_array(), hi.as_dvec3().to_array()];
    let n = items.len();
    if n <= leaf_max || depth >= MAX_DEPTH {
        nodes[index].first = offset as u32;
        nodes[index].count = n as u32;
        return None;
    }
    let extent = chi - clo;
    let widest = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    // Binned SAH over the three axes of the centres: the cheapest split, the lower axis
    // on a tie.
    let best = sah(items, clo, extent);
    if let Some((cost, _, _)) = best {
        let area = surface_area(lo, hi);
        if n <= LEAF_SAH_MAX.max(leaf_max) && n as f64 * area <= TRAVERSE_COST * area + cost {
            nodes[index].first = offset as u32;
            nodes[index].count = n as u32;
            return None;
        }
    }
    let axis = best.map_or(widest, |b| b.1);
    let mid = match best {
        Some((_, axis, split)) => {
            let k = BINS as f32 / extent[axis];
            partition(items, |it| bin(it.centre[axis], clo[axis], k) <= split)
        }
        None => n / 2,
    };
    if mid == 0 || mid == n {
        // All centres in one bin (or all equal): split at the median.
        items.select_nth_unstable_by(n / 2, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
        return Some(n / 2);
    }
    Some(mid)
}

/// Moves the items satisfying `pred` to the front; returns how many there are.
fn partition(items: &mut [Item], pred: impl Fn(&Item) -> bool) -> usize {
    let mut i = 0;
    for j in 0..items.len() {
        if pred(&items[j]) {
            items.swap(i, j);
            i += 1;
        }
    }
    i
}
