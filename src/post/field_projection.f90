!> Projection by collocation (Code_Aster's PROJ_CHAMP METHODE='COLLOCATION', U4.72.05): each
!> node of a target mesh takes the values of a nodal field of a source mesh interpolated by
!> the shape functions of the source cell that contains it.
!>
!> The search, as Code_Aster's pj2dco / pj3dco: every source cell is cut into simplices of
!> its corners (a triangle, a quadrangle into (1 2 3) and (1 3 4), a segment); a target
!> point is located by the closest point of each simplex (in 3D for cells of a surface in
!> space, CAS_FIGURE '2.5D': the distance then includes the distance to the cell's plane).
!> The cell at the smallest distance wins (the first in cell order among equals: on the
!> edges between cells a continuous field has one value). Its reference coordinates are
!> the barycentric combination of the simplex's corners' reference coordinates; for a cell
!> whose geometric map is not affine on that simplex (a distorted quadrangle, a curved
!> quadratic cell) they are then refined by Newton on the isoparametric map (as
!> Code_Aster's reereg), so that a field the cell represents exactly (a linear field on any
!> quadrangle) is projected exactly. The weights are the cell type's shape functions there.
!>
!> A point in no cell takes the nearest cell (its closest point), unless it is farther
!> than DISTANCE_MAX: it is then not projected. The correspondence (cell, weights,
!> distance per target node) is kept so that several fields share one search.
module field_projection
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t
    use mesh_cell_shapes, only: cell_shape, cell_reference_nodes, CELL_TYPE_NODES, &
        CELL_TYPE_DIM, CELL_SEG2, CELL_SEG3, CELL_TRIA3, CELL_TRIA6, CELL_QUAD4, CELL_QUAD8, &
        CELL_QUAD9, MAX_CELL_NODES
    use field_types, only: field_t, field_init_nodes, FIELD_NOEU
    implicit none
    private

    !> Relative size (to the cell's diameter) under which a point is inside a cell.
    real(dp), parameter :: INSIDE_TOLERANCE = 1.0e-10_dp
    !> Newton iterations of the inverse isoparametric map, and its relative tolerance.
    integer, parameter :: NEWTON_ITERATIONS = 30
    real(dp), parameter :: NEWTON_TOLERANCE = 1.0e-14_dp

    !> Where each target node was found.
    type, public :: projection_t
        integer(i4) :: n_targets = 0                    !< nodes of the target mesh
        logical, allocatable :: projected(:)            !< (n_targets)
        integer(i4), allocatable :: cell(:)             !< (n_targets) source cell
        real(dp), allocatable :: weights(:, :)          !< (MAX_CELL_NODES, n_targets)
        real(dp), allocatable :: distance(:)            !< (n_targets) 0 when inside
        logical, allocatable :: outside(:)              !< (n_targets) found in no cell
    end type projection_t

    !> A uniform grid of buckets over the source cells' bounding boxes.
    type :: bucket_grid_t
        real(dp) :: origin(3) = 0.0_dp, step(3) = 1.0_dp
        integer(i4) :: n(3) = 1
        integer(i4), allocatable :: ptr(:), items(:)
    end type bucket_grid_t

    public :: projection_build, projection_merge, project_node_field, cells_of_dimension

contains

    !> The cells of `cells` whose topological dimension is `dim` (1 or 2).
    function cells_of_dimension(mesh, cells, dim) result(kept)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), dim
        integer(i4), allocatable :: kept(:)
        integer(i4) :: k
        kept = pack(cells, [(CELL_TYPE_DIM(mesh%cell_type(cells(k))) == dim .and. &
            is_projectable(mesh%cell_type(cells(k))), k = 1, size(cells, kind=i4))])
    end function cells_of_dimension

    pure logical function is_projectable(ctype)
        integer(i4), intent(in) :: ctype
        is_projectable = any(ctype == [CELL_SEG2, CELL_SEG3, CELL_TRIA3, CELL_TRIA6, &
            CELL_QUAD4, CELL_QUAD8, CELL_QUAD9])
    end function is_projectable

    !> Locates the nodes `targets` of `target` in the cells `cells` of `source`.
    !>  max_distance : < 0 for none (every node is projected on its nearest cell)
    !>  proj         : out, on target%n_nodes nodes; nodes not in `targets` not projected
    !>  st           : STATUS_MODEL_ERROR when there is no cell to project on
    subroutine projection_build(source, cells, target, targets, max_distance, proj, st)
        type(mesh_t), intent(in) :: source, target
        integer(i4), intent(in) :: cells(:), targets(:)
        real(dp), intent(in) :: max_distance
        type(projection_t), intent(out) :: proj
        type(status_t), intent(out) :: st
        type(bucket_grid_t) :: grid
        real(dp), allocatable :: box(:, :, :), size_of(:)
        real(dp) :: p(3), w(MAX_CELL_NODES), d, best_d, best_w(MAX_CELL_NODES)
        integer(i4) :: k, j, c, best, b
        proj%n_targets = target%n_nodes
        allocate (proj%projected(target%n_nodes), source=.false.)
        allocate (proj%outside(target%n_nodes), source=.false.)
        allocate (proj%cell(target%n_nodes), source=0_i4)
        allocate (proj%weights(MAX_CELL_NODES, target%n_nodes), source=0.0_dp)
        allocate (proj%distance(target%n_nodes), source=0.0_dp)
        if (size(cells) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'no cell of the source to project on ' // &
                '(segments, triangles or quadrangles)')
            return
        end if
        allocate (box(3, 2, size(cells)), size_of(size(cells)))
        do k = 1, size(cells, kind=i4)
            call cell_box(source, cells(k), box(:, :, k))
            size_of(k) = norm2(box(:, 2, k) - box(:, 1, k))
        end do
        call grid_build(box, grid)
        do j = 1, size(targets, kind=i4)
            p = target%coords(:, targets(j))
            best = 0
            best_d = huge(1.0_dp)
            b = grid_bucket(grid, p)
            if (b > 0) then         ! the cells whose box holds p: inside one of them?
                do k = grid%ptr(b), grid%ptr(b + 1) - 1
                    c = grid%items(k)
                    if (any(p < box(:, 1, c) - INSIDE_TOLERANCE * size_of(c)) .or. &
                        any(p > box(:, 2, c) + INSIDE_TOLERANCE * size_of(c))) cycle
                    call locate_in_cell(source, cells(c), p, w, d)
                    if (d < best_d) then
                        best_d = d
                        best = c
                        best_w = w
                    end if
                    if (best_d <= INSIDE_TOLERANCE * size_of(c)) exit
                end do
            end if
            if (best == 0) then
                best_d = huge(1.0_dp)
            else if (best_d > INSIDE_TOLERANCE * size_of(best)) then
                best = 0
                best_d = huge(1.0_dp)
            end if
            if (best == 0) then     ! in no cell: the nearest one, over all cells
                do c = 1, size(cells, kind=i4)
                    call locate_in_cell(source, cells(c), p, w, d)
                    if (d < best_d) then
                        best_d = d
                        best = c
                        best_w = w
                    end if
                end do
                proj%outside(targets(j)) = best_d > INSIDE_TOLERANCE * size_of(best)
            end if
            if (max_distance >= 0.0_dp .and. proj%outside(targets(j)) .and. &
                best_d > max_distance) cycle
            proj%projected(targets(j)) = .true.
            proj%cell(targets(j)) = cells(best)
            proj%weights(:, targets(j)) = best_w
            proj%distance(targets(j)) = merge(best_d, 0.0_dp, proj%outside(targets(j)))
        end do
    end subroutine projection_build

    !> `later` over `proj` where `later` projects a node (VIS_A_VIS occurrences in order).
    subroutine projection_merge(proj, later)
        type(projection_t), intent(inout) :: proj
        type(projection_t), intent(in) :: later
        integer(i4) :: n
        if (.not. allocated(proj%projected)) then
            proj = later
            return
        end if
        do n = 1, proj%n_targets
            if (.not. later%projected(n)) cycle
            proj%projected(n) = .true.
            proj%outside(n) = later%outside(n)
            proj%cell(n) = later%cell(n)
            proj%weights(:, n) = later%weights(:, n)
            proj%distance(n) = later%distance(n)
        end do
    end subroutine projection_merge

    !> The nodal field `f` of `source` at the projected nodes of the target: each component
    !> the cell's nodes of non-zero weight all carry; `prol` (when present) at the nodes not
    !> projected, for every component.
    subroutine project_node_field(f, source, proj, out, st, prol)
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: source
        type(projection_t), intent(in) :: proj
        type(field_t), intent(out) :: out
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: prol
        integer(i4) :: n, i, k, first, nn, node
        real(dp) :: v
        logical :: ok
        if (f%location /= FIELD_NOEU) then
            call set_error(st, STATUS_MODEL_ERROR, 'the projection of fields by element ' // &
                '(ELGA, ELNO, ELEM) is not built in parasol (nodal fields are)')
            return
        end if
        if (f%n_nodes /= source%n_nodes) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field has ' // to_text(f%n_nodes) // &
                ' nodes, the source mesh ' // to_text(source%n_nodes))
            return
        end if
        call field_init_nodes(out, f%quantity, f%components, proj%n_targets, st)
        if (st%failed()) return
        do n = 1, proj%n_targets
            if (.not. proj%projected(n)) then
                if (present(prol)) then
                    out%node_values(:, n) = prol
                    out%node_has(:, n) = .true.
                end if
                cycle
            end if
            first = source%cell_ptr(proj%cell(n))
            nn = CELL_TYPE_NODES(source%cell_type(proj%cell(n)))
            do i = 1, size(f%components)
                v = 0.0_dp
                ok = .true.
                do k = 1, nn
                    if (.not. abs(proj%weights(k, n)) > 0.0_dp) cycle
                    node = source%cell_nodes(first + k - 1)
                    if (.not. f%node_has(i, node)) then
                        ok = .false.
                        exit
                    end if
                    v = v + proj%weights(k, n) * f%node_values(i, node)
                end do
                if (ok) then
                    out%node_values(i, n) = v
                    out%node_has(i, n) = .true.
                else if (present(prol)) then
                    out%node_values(i, n) = prol
                    out%node_has(i, n) = .true.
                end if
            end do
        end do
    end subroutine project_node_field

    ! ---- geometry -------------------------------------------------------------------------

    ! Bounding box of cell c: box(:, 1) lower, box(:, 2) upper corner.
    subroutine cell_box(mesh, c, box)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(out) :: box(3, 2)
        integer(i4) :: k
        box(:, 1) = huge(1.0_dp)
        box(:, 2) = -huge(1.0_dp)
        do k = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
            box(:, 1) = min(box(:, 1), mesh%coords(:, mesh%cell_nodes(k)))
            box(:, 2) = max(box(:, 2), mesh%coords(:, mesh%cell_nodes(k)))
        end do
    end subroutine cell_box

    !> The weights (shape functions at the located point) and the distance of p to cell c.
    subroutine locate_in_cell(mesh, c, p, w, d)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: p(3)
        real(dp), intent(out) :: w(MAX_CELL_NODES), d
        real(dp) :: x(3, MAX_CELL_NODES), ref(2, MAX_CELL_NODES), xi(2), lam(3), dt, &
            best_xi(2), dn(2, MAX_CELL_NODES)
        integer(i4) :: ctype, nn, t
        integer(i4), parameter :: TRI(3, 2) = reshape([1, 2, 3, 1, 3, 4], [3, 2])
        ctype = mesh%cell_type(c)
        nn = CELL_TYPE_NODES(ctype)
        x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c) + nn - 1))
        call cell_reference_nodes(ctype, ref)
        d = huge(1.0_dp)
        best_xi = 0.0_dp
        select case (CELL_TYPE_DIM(ctype))
        case (1)
            call closest_on_segment(p, x(:, 1), x(:, 2), lam(1), d)
            best_xi = (1.0_dp - lam(1)) * ref(:, 1) + lam(1) * ref(:, 2)
        case (2)
            do t = 1, merge(2, 1, any(ctype == [CELL_QUAD4, CELL_QUAD8, CELL_QUAD9]))
                call closest_on_triangle(p, x(:, TRI(1, t)), x(:, TRI(2, t)), &
                    x(:, TRI(3, t)), lam, dt)
                if (dt < d) then
                    d = dt
                    xi = lam(1) * ref(:, TRI(1, t)) + lam(2) * ref(:, TRI(2, t)) + &
                        lam(3) * ref(:, TRI(3, t))
                    best_xi = xi
                end if
            end do
        end select
        if (ctype /= CELL_TRIA3 .and. ctype /= CELL_SEG2) call refine(ctype, nn, x, p, best_xi, d)
        w = 0.0_dp
        call cell_shape(ctype, best_xi(1), best_xi(2), w(1:nn), dn(:, 1:nn))
    end subroutine locate_in_cell

    ! Newton (Gauss-Newton for a surface in space) on x(xi) = p from the simplex estimate;
    ! kept when it converges to a point of the reference cell no farther from p.
    subroutine refine(ctype, nn, x, p, xi, d)
        integer(i4), intent(in) :: ctype, nn
        real(dp), intent(in) :: x(3, MAX_CELL_NODES), p(3)
        real(dp), intent(inout) :: xi(2), d
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), jac(3, 2), r(3), a(2, 2), &
            b(2), det, step(2), trial(2), scale
        integer :: it, dim
        dim = CELL_TYPE_DIM(ctype)
        trial = xi
        scale = maxval(abs(x(:, 1:nn) - spread(x(:, 1), 2, nn))) + tiny(1.0_dp)
        do it = 1, NEWTON_ITERATIONS
            call cell_shape(ctype, trial(1), trial(2), n(1:nn), dn(:, 1:nn))
            r = p - matmul(x(:, 1:nn), n(1:nn))
            jac(:, 1) = matmul(x(:, 1:nn), dn(1, 1:nn))
            jac(:, 2) = matmul(x(:, 1:nn), dn(2, 1:nn))
            if (dim == 1) then
                det = dot_product(jac(:, 1), jac(:, 1))
                if (.not. det > 0.0_dp) return
                step = [dot_product(jac(:, 1), r) / det, 0.0_dp]
            else
                a = matmul(transpose(jac), jac)
                b = matmul(transpose(jac), r)
                det = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
                if (.not. abs(det) > 0.0_dp) return
                step = [a(2, 2) * b(1) - a(1, 2) * b(2), a(1, 1) * b(2) - a(2, 1) * b(1)] / det
            end if
            trial = trial + step
            if (any(abs(trial) > 10.0_dp)) return
            if (maxval(abs(step)) <= NEWTON_TOLERANCE) exit
        end do
        if (.not. in_reference(ctype, trial)) return
        call cell_shape(ctype, trial(1), trial(2), n(1:nn), dn(:, 1:nn))
        r = p - matmul(x(:, 1:nn), n(1:nn))
        if (norm2(r) <= d + INSIDE_TOLERANCE * scale) then
            xi = trial
            d = norm2(r)
        end if
    end subroutine refine

    pure logical function in_reference(ctype, xi)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xi(2)
        real(dp), parameter :: EPS = 1.0e-9_dp
        select case (ctype)
        case (CELL_SEG2, CELL_SEG3)
            in_reference = abs(xi(1)) <= 1.0_dp + EPS
        case (CELL_TRIA3, CELL_TRIA6)
            in_reference = xi(1) >= -EPS .and. xi(2) >= -EPS .and. xi(1) + xi(2) <= 1.0_dp + EPS
        case default
            in_reference = all(abs(xi) <= 1.0_dp + EPS)
        end select
    end function in_reference

    ! Closest point of segment [a, b] to p: its parameter t in [0, 1] and the distance.
    pure subroutine closest_on_segment(p, a, b, t, d)
        real(dp), intent(in) :: p(3), a(3), b(3)
        real(dp), intent(out) :: t, d
        real(dp) :: ab(3), l2
        ab = b - a
        l2 = dot_product(ab, ab)
        t = 0.0_dp
        if (l2 > 0.0_dp) t = min(1.0_dp, max(0.0_dp, dot_product(p - a, ab) / l2))
        d = norm2(p - (a + t * ab))
    end subroutine closest_on_segment

    ! Closest point of triangle (a, b, c) to p (in space): its barycentric coordinates
    ! lam (on a, b, c) and the distance (the Voronoi regions of the vertices, edges, face).
    pure subroutine closest_on_triangle(p, a, b, c, lam, d)
        real(dp), intent(in) :: p(3), a(3), b(3), c(3)
        real(dp), intent(out) :: lam(3), d
        real(dp) :: ab(3), ac(3), ap(3), bp(3), cp(3), d1, d2, d3, d4, d5, d6, va, vb, vc, &
            v, w, den
        ab = b - a
        ac = c - a
        ap = p - a
        d1 = dot_product(ab, ap)
        d2 = dot_product(ac, ap)
        if (d1 <= 0.0_dp .and. d2 <= 0.0_dp) then
            lam = [1.0_dp, 0.0_dp, 0.0_dp]
        else
            bp = p - b
            d3 = dot_product(ab, bp)
            d4 = dot_product(ac, bp)
            cp = p - c
            d5 = dot_product(ab, cp)
            d6 = dot_product(ac, cp)
            vc = d1 * d4 - d3 * d2
            vb = d5 * d2 - d1 * d6
            va = d3 * d6 - d5 * d4
            if (d3 >= 0.0_dp .and. d4 <= d3) then
                lam = [0.0_dp, 1.0_dp, 0.0_dp]
            else if (d6 >= 0.0_dp .and. d5 <= d6) then
                lam = [0.0_dp, 0.0_dp, 1.0_dp]
            else if (vc <= 0.0_dp .and. d1 >= 0.0_dp .and. d3 <= 0.0_dp) then
                v = d1 / (d1 - d3)
                lam = [1.0_dp - v, v, 0.0_dp]
            else if (vb <= 0.0_dp .and. d2 >= 0.0_dp .and. d6 <= 0.0_dp) then
                w = d2 / (d2 - d6)
                lam = [1.0_dp - w, 0.0_dp, w]
            else if (va <= 0.0_dp .and. (d4 - d3) >= 0.0_dp .and. (d5 - d6) >= 0.0_dp) then
                w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
                lam = [0.0_dp, 1.0_dp - w, w]
            else
                den = va + vb + vc
                if (.not. abs(den) > 0.0_dp) then      ! a degenerate triangle: its vertex a
                    lam = [1.0_dp, 0.0_dp, 0.0_dp]
                else
                    v = vb / den
                    w = vc / den
                    lam = [1.0_dp - v - w, v, w]
                end if
            end if
        end if
        d = norm2(p - (lam(1) * a + lam(2) * b + lam(3) * c))
    end subroutine closest_on_triangle

    ! ---- buckets --------------------------------------------------------------------------

    ! A grid of about one bucket per cell over the boxes; each cell in every bucket its box
    ! meets.
    subroutine grid_build(box, grid)
        real(dp), intent(in) :: box(:, :, :)
        type(bucket_grid_t), intent(out) :: grid
        real(dp) :: lo(3), hi(3), extent(3), h
        integer(i4) :: k, lo_i(3), hi_i(3), i, j, l, b, n_buckets
        integer(i4), allocatable :: count(:)
        lo = minval(box(:, 1, :), dim=2)
        hi = maxval(box(:, 2, :), dim=2)
        extent = hi - lo
        h = sum([(norm2(box(:, 2, k) - box(:, 1, k)), k = 1, size(box, 3, kind=i4))]) / &
            real(size(box, 3), dp)
        if (.not. h > 0.0_dp) h = max(maxval(extent), 1.0_dp)
        grid%origin = lo
        do k = 1, 3
            grid%n(k) = int(min(real(200, dp), max(1.0_dp, extent(k) / h)), i4)
            grid%step(k) = h               ! a flat direction: one bucket
            if (extent(k) > 0.0_dp) grid%step(k) = extent(k) / real(grid%n(k), dp)
        end do
        n_buckets = product(grid%n)
        allocate (count(n_buckets + 1), source=0_i4)
        do l = 1, 2                 ! count, then fill
            if (l == 2) then
                grid%ptr = [1_i4, 1_i4 + [(sum(count(1:b)), b = 1, n_buckets)]]
                allocate (grid%items(grid%ptr(n_buckets + 1) - 1))
                count = 0
            end if
            do k = 1, size(box, 3, kind=i4)
                lo_i = index_of(grid, box(:, 1, k))
                hi_i = index_of(grid, box(:, 2, k))
                do i = lo_i(1), hi_i(1)
                    do j = lo_i(2), hi_i(2)
                        do b = lo_i(3), hi_i(3)
                            associate (at => i + grid%n(1) * ((j - 1) + grid%n(2) * (b - 1)))
                                count(at) = count(at) + 1
                                if (l == 2) grid%items(grid%ptr(at) + count(at) - 1) = k
                            end associate
                        end do
                    end do
                end do
            end do
        end do
    end subroutine grid_build

    pure function index_of(grid, p) result(ijk)
        type(bucket_grid_t), intent(in) :: grid
        real(dp), intent(in) :: p(3)
        integer(i4) :: ijk(3)
        integer :: k
        real(dp) :: t
        do k = 1, 3
            t = (p(k) - grid%origin(k)) / grid%step(k)
            ijk(k) = int(min(real(grid%n(k), dp), max(1.0_dp, 1.0_dp + aint(t))), i4)
        end do
    end function index_of

    ! The bucket of p, 0 when p is outside the grid's box (by more than the tolerance).
    pure integer(i4) function grid_bucket(grid, p) result(b)
        type(bucket_grid_t), intent(in) :: grid
        real(dp), intent(in) :: p(3)
        integer(i4) :: ijk(3)
        real(dp) :: hi(3), tol(3)
        hi = grid%origin + grid%step * real(grid%n, dp)
        tol = 1.0e-9_dp * max(hi - grid%origin, maxval(hi - grid%origin))
        b = 0
        if (any(p < grid%origin - tol) .or. any(p > hi + tol)) return
        ijk = index_of(grid, p)
        b = ijk(1) + grid%n(1) * ((ijk(2) - 1) + grid%n(2) * (ijk(3) - 1))
    end function grid_bucket

end module field_projection
