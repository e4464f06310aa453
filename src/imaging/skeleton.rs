//! Zhang–Suen thinning (T. Y. Zhang and C. Y. Suen, "A fast parallel
//! algorithm for thinning digital patterns", CACM 1984), visiting only the
//! current border pixels so large masks thin in near-linear time.

use super::Mask;

/// The 8-connected, one-pixel-wide skeleton of the foreground of `mask`.
///
/// ```
/// use nrgdb::imaging::{binarize, skeletonize};
/// // A 3-pixel-thick bar thins to its middle row.
/// let m = binarize(7, 3, &[255; 21], 250);
/// let s = skeletonize(&m);
/// assert!(s.enumerate_pixels().all(|(_, y, p)| p[0] == 0 || y == 1));
/// assert!(s.as_raw().iter().filter(|&&p| p != 0).count() >= 3);
/// ```
pub fn skeletonize(mask: &Mask) -> Mask {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let mut img: Vec<bool> = mask.as_raw().iter().map(|&p| p != 0).collect();
    let at = |img: &[bool], x: isize, y: isize| -> bool {
        x >= 0 && y >= 0 && (x as usize) < w && (y as usize) < h && img[y as usize * w + x as usize]
    };
    let mut candidates: Vec<usize> = (0..w * h).filter(|&i| img[i]).collect();
    let mut in_list = vec![false; w * h];
    let mut to_delete = Vec::new();
    loop {
        let mut changed = false;
        for step in 0..2 {
            to_delete.clear();
            for &i in &candidates {
                if !img[i] {
                    continue;
                }
                let (x, y) = ((i % w) as isize, (i / w) as isize);
                // P2..P9 clockwise from north.
                let p = [
                    at(&img, x, y - 1),
                    at(&img, x + 1, y - 1),
                    at(&img, x + 1, y),
                    at(&img, x + 1, y + 1),
                    at(&img, x, y + 1),
                    at(&img, x - 1, y + 1),
                    at(&img, x - 1, y),
                    at(&img, x - 1, y - 1),
                ];
                let b = p.iter().filter(|&&v| v).count();
                if !(2..=6).contains(&b) {
                    continue;
                }
                let a = (0..8).filter(|&k| !p[k] && p[(k + 1) % 8]).count();
                if a != 1 {
                    continue;
                }
                let (p2, p4, p6, p8) = (p[0], p[2], p[4], p[6]);
                let ok = if step == 0 {
                    // P2·P4·P6 = 0 and P4·P6·P8 = 0
                    !(p4 && p6 && (p2 || p8))
                } else {
                    // P2·P4·P8 = 0 and P2·P6·P8 = 0
                    !(p2 && p8 && (p4 || p6))
                };
                if ok {
                    to_delete.push(i);
                }
            }
            if !to_delete.is_empty() {
                changed = true;
            }
            for &i in &to_delete {
                img[i] = false;
            }
            // Next candidates: surviving foreground pixels next to a deleted one.
            let mut next = Vec::new();
            for &i in &to_delete {
                let (x, y) = ((i % w) as isize, (i / w) as isize);
                for dy in -1..=1 {
                    for dx in -1..=1 {
                        if at(&img, x + dx, y + dy) {
                            let j = (y + dy) as usize * w + (x + dx) as usize;
                            if !in_list[j] {
                                in_list[j] = true;
                                next.push(j);
                            }
                        }
                    }
                }
            }
            // Pixels checked but not deleted may become deletable later in the other sub-step.
            for &i in &candidates {
                if img[i] && !in_list[i] {
                    in_list[i] = true;
                    next.push(i);
                }
            }
            for &j in &next {
                in_list[j] = false;
            }
            if step == 1 || !to_delete.is_empty() || !next.is_empty() {
                candidates = next;
            }
        }
        if !changed {
            break;
        }
    }
    let data = img.iter().map(|&v| if v { 255 } else { 0 }).collect();
    Mask::from_raw(mask.width(), mask.height(), data).unwrap_or_else(|| mask.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{ascii_mask, label_components, mask_ascii};

    #[test]
    fn a_thick_bar_thins_to_a_line() {
        let m = ascii_mask(
            "..........
             .########.
             .########.
             .########.
             ..........",
        );
        let s = skeletonize(&m);
        let text = mask_ascii(&s);
        let rows: Vec<&str> = text.lines().collect();
        assert!(
            rows.iter()
                .enumerate()
                .all(|(y, r)| y == 2 || !r.contains('#')),
            "{rows:?}"
        );
        let n = rows[2].matches('#').count();
        assert!((4..=6).contains(&n), "{rows:?}");
    }

    #[test]
    fn a_ring_keeps_its_hole_and_stays_connected() {
        let m = ascii_mask(
            "#######
             #######
             ##...##
             ##...##
             ##...##
             #######
             #######",
        );
        let s = skeletonize(&m);
        assert_eq!(label_components(&s, true).count, 1);
        // The hole is not filled: still one background component inside.
        let mut inv = s.clone();
        inv.iter_mut().for_each(|p| *p = 255 - *p);
        assert!(label_components(&inv, false).count >= 2);
        // Thinner than the input.
        let n = s.as_raw().iter().filter(|&&p| p != 0).count();
        assert!((16..30).contains(&n), "{n}");
    }

    #[test]
    fn an_l_shape_stays_connected() {
        let m = ascii_mask(
            "###.....
             ###.....
             ###.....
             ########
             ########
             ########",
        );
        let s = skeletonize(&m);
        assert_eq!(label_components(&s, true).count, 1);
        assert!(s.as_raw().iter().filter(|&&p| p != 0).count() >= 6);
    }
}
