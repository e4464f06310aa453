//! Bresenham's line algorithm (Bresenham 1965) over grid cells.

/// Calls `visit(x, y)` for every cell of the 8-connected digital line from
/// `(x0, y0)` to `(x1, y1)`, both ends included, in order from the start.
///
/// ```
/// use nrgdb::sim::bresenham;
/// let mut cells = Vec::new();
/// bresenham(0, 0, 3, 1, |x, y| cells.push((x, y)));
/// assert_eq!(cells, [(0, 0), (1, 0), (2, 1), (3, 1)]);
/// ```
#[inline]
pub fn bresenham(x0: i64, y0: i64, x1: i64, y1: i64, mut visit: impl FnMut(i64, i64)) {
    let dx = (x1 - x0).abs();
    let dy = -(y1 - y0).abs();
    let sx = if x0 < x1 { 1 } else { -1 };
    let sy = if y0 < y1 { 1 } else { -1 };
    let (mut x, mut y) = (x0, y0);
    let mut err = dx + dy;
    loop {
        visit(x, y);
        if x == x1 && y == y1 {
            break;
        }
        let e2 = 2 * err;
        if e2 >= dy {
            err += dy;
            x += sx;
        }
        if e2 <= dx {
            err += dx;
            y += sy;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<(i64, i64)> {
        let mut v = Vec::new();
        bresenham(x0, y0, x1, y1, |x, y| v.push((x, y)));
        v
    }

    #[test]
    fn single_cell_and_axis_lines() {
        assert_eq!(line(2, 2, 2, 2), [(2, 2)]);
        assert_eq!(line(0, 0, 0, -3), [(0, 0), (0, -1), (0, -2), (0, -3)]);
        assert_eq!(line(3, 1, 0, 1), [(3, 1), (2, 1), (1, 1), (0, 1)]);
    }

    #[test]
    fn lines_are_8_connected_and_symmetric_in_length() {
        for (x1, y1) in [(7, 3), (-5, 9), (-8, -2), (4, -11), (6, 6)] {
            let v = line(0, 0, x1, y1);
            assert_eq!(v.len() as i64, x1.abs().max(y1.abs()) + 1);
            assert_eq!(*v.last().unwrap(), (x1, y1));
            for w in v.windows(2) {
                assert!((w[1].0 - w[0].0).abs() <= 1 && (w[1].1 - w[0].1).abs() <= 1);
            }
        }
    }
}
