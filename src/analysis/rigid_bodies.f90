!> Bodies held only by springs, and their rigid modes (doc/analysis.md, "Rigid modes").
!>
!> A body is a connected set of plate (DKT/DKQ) or plane-solid cells (cells sharing nodes).
!> Its rigid motions have zero energy in those elements: K_b R = 0, computed from the
!> geometry, not from the matrix:
!>  - plane solids (D_PLAN, C_PLAN: DX DY): the two translations and the rotation about Z;
!>  - plates (DX..DRZ): the three translations (rotations 0); rotations about an axis w
!>    (u = w x (x - xc), nodal rotations w) when w is normal to every cell's normal: the
!>    projected arm of each cell is then its true arm and the fictitious drilling stiffness
!>    (about the cell normal, COEF_RIGI_DRZ) sees nothing; on a flat body also the rotation
!>    about the normal with the nodal rotations 0 (membrane rigid motion, no drilling).
!>    A body with a warped cell keeps its translations only (a warped cell's rigid rotation
!>    stretches its membrane: doc/analysis.md "Round-off").
!> The body's imposed equations (DDL_IMPO, AFFE_CHAR_CINE: map%imposed) hold the modes that
!> move them: the modes left are the combinations that are zero on every imposed equation
!> and satisfy every linear relation on the body (the null space of those rows). A body is
!> held by springs only (or by nothing) when modes are left; they are kept apart by the two-level solver (two_level_solver), with one
!> anchor equation per mode: translations (DX, DY, DZ) of the body's free equations chosen
!> by pivoted Gram-Schmidt on the rows of the modes (the most independent rows: far-apart
!> nodes, e.g. three corners for a plate's bending modes), and the modes recombined so that
!> mode k moves anchor k by 1 and the other anchors by 0.
module rigid_bodies
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    use mesh_types, only: cell_name
    use model_types, only: is_plate, is_plane_solid
    use model_dof_numbering, only: describe_equation, N_COMPONENTS, DOF_DZ
    use assembly_system, only: structure_t, assembly_map_t, is_body_cell
    use analysis_log, only: analysis_log_t, log_add
    use huge_pages, only: advise_huge_pages
    implicit none
    private

    !> A cell whose nodes leave its mean plane by more than this fraction of its size is
    !> warped (its rigid rotations are not zero-energy motions of the plate element); a
    !> body whose nodes leave the body's plane by more than this fraction of its size is not
    !> flat. Round-off of coordinates written with ~15 digits stays far below.
    real(dp), parameter :: FLAT_TOLERANCE = 1.0e-12_dp
    !> Two cell normals are parallel (the body is flat) when |n1 x n2| is below this.
    real(dp), parameter :: PARALLEL_TOLERANCE = 1.0e-12_dp
    !> A direction whose constraint energy (sum of the squared values of the modes on the
    !> imposed equations, modes of unit size) is below this fraction of the largest is not
    !> held by them: round-off level.
    real(dp), parameter :: HELD_TOLERANCE = 64.0_dp * epsilon(1.0_dp)
    !> The largest rigid-mode count of a body (3 translations + 3 rotations).
    integer(i4), parameter :: MAX_BODY_MODES = 6
    !> Bodies described one by one in the .mess before the list is summed up.
    integer(i4), parameter :: LIST_BODIES = 4

    !> The rigid modes of the bodies held only by springs (or nothing).
    type, public :: rigid_modes_t
        integer(i4) :: n_modes = 0
        integer(i4) :: n_bodies = 0                 !< bodies (plates, plane solids)
        integer(i4) :: n_floating = 0               !< of them with modes left
        real(dp), allocatable :: r(:, :)            !< (n_free, n_modes), identity on anchors
        integer(i4), allocatable :: anchors(:)      !< (n_modes) free equations
        integer(i4), allocatable :: body_of_mode(:) !< (n_modes)
    end type rigid_modes_t

    !> One candidate motion of a body: a translation along `axis`, or a rotation about
    !> `axis` through the centroid (nodal rotations = axis when rotate_dofs).
    !> The modes of one body on its equations (original numbering), with their anchors.
    type :: body_modes_t
        integer(i4), allocatable :: eqs(:)          !< the body's equations
        real(dp), allocatable :: values(:, :)       !< (size(eqs), m), identity on anchors
        integer(i4), allocatable :: anchors(:)      !< (m) original equation numbers
    end type body_modes_t

    type :: motion_t
        logical :: rotation = .false.
        logical :: rotate_dofs = .false.
        real(dp) :: axis(3) = 0.0_dp
    end type motion_t

    public :: find_rigid_modes

contains

    !> Finds the bodies, their rigid modes left free by the imposed equations, and anchors
    !> (module header); the .mess says which bodies are held only by springs and how their
    !> modes are treated.
    !>  s, map : in, the structure and its free numbering (map%imposed)
    !>  modes  : out, n_modes = 0 when every body is held
    !>  log    : inout, the .mess lines
    !>  st     : out, STATUS_INTERNAL if the anchors cannot be chosen (no translation left)
    subroutine find_rigid_modes(s, map, modes, log, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(rigid_modes_t), intent(out) :: modes
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        type(body_modes_t), allocatable :: found(:)
        integer(i4), allocatable :: body_of_node(:), nodes(:), cells(:), row_ptr(:), &
            row_list(:)
        integer(i4) :: b, i, k, m, col
        character(len=:), allocatable :: line
        call label_bodies(s, map, body_of_node, modes%n_bodies)
        call relations_of_bodies(s, map, body_of_node, modes%n_bodies, row_ptr, row_list)
        allocate (found(modes%n_bodies))
        do b = 1, modes%n_bodies
            call body_members(s, map, body_of_node, b, nodes, cells)
            call body_modes(s, map, nodes, cells, body_of_node, b, &
                row_list(row_ptr(b):row_ptr(b + 1) - 1), found(b), line, st)
            if (st%failed()) return
            if (size(found(b)%anchors) == 0) cycle
            modes%n_floating = modes%n_floating + 1
            if (modes%n_floating <= LIST_BODIES) call log_add(log, 'rigid modes: ' // line)
        end do
        if (modes%n_floating > LIST_BODIES) call log_add(log, 'rigid modes: ' // &
            to_text(modes%n_floating - LIST_BODIES) // ' more bodies held only by springs')
        m = 0
        do b = 1, modes%n_bodies
            m = m + size(found(b)%anchors, kind=i4)
        end do
        modes%n_modes = m
        allocate (modes%r(map%n_free, m))
        call advise_huge_pages(modes%r)
        modes%r = 0.0_dp
        allocate (modes%anchors(m), modes%body_of_mode(m))
        col = 0
        do b = 1, modes%n_bodies
            do k = 1, size(found(b)%anchors)
                col = col + 1
                modes%anchors(col) = map%free_eq(found(b)%anchors(k))
                modes%body_of_mode(col) = b
                do i = 1, size(found(b)%eqs)
                    if (map%free_eq(found(b)%eqs(i)) == 0) cycle
                    modes%r(map%free_eq(found(b)%eqs(i)), col) = found(b)%values(i, k)
                end do
            end do
        end do
    end subroutine find_rigid_modes

    !> Numbers the bodies: body_of_node(node) = its body (0: no plate or plane-solid cell),
    !> connected components of the body cells by shared nodes (union-find).
    subroutine label_bodies(s, map, body_of_node, n_bodies)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), allocatable, intent(out) :: body_of_node(:)
        integer(i4), intent(out) :: n_bodies
        integer(i4), allocatable :: parent(:), label(:)
        integer(i4) :: k, c, p, first, root
        allocate (parent(s%mesh%n_nodes), source=0_i4)     ! 0: not in a body
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (.not. is_body_cell(s, c)) cycle
            first = s%mesh%cell_nodes(s%mesh%cell_ptr(c))
            if (parent(first) == 0) parent(first) = first
            do p = s%mesh%cell_ptr(c) + 1, s%mesh%cell_ptr(c + 1) - 1
                associate (node => s%mesh%cell_nodes(p))
                    if (parent(node) == 0) parent(node) = node
                    call unite(parent, first, node)
                end associate
            end do
        end do
        allocate (label(s%mesh%n_nodes), source=0_i4)
        allocate (body_of_node(s%mesh%n_nodes), source=0_i4)
        n_bodies = 0
        do k = 1, s%mesh%n_nodes
            if (parent(k) == 0) cycle
            root = find_root(parent, k)
            if (label(root) == 0) then
                n_bodies = n_bodies + 1
                label(root) = n_bodies
            end if
            body_of_node(k) = label(root)
        end do
    end subroutine label_bodies

    integer(i4) function find_root(parent, i) result(root)
        integer(i4), intent(inout) :: parent(:)
        integer(i4), intent(in) :: i
        integer(i4) :: j, next
        root = i
        do while (parent(root) /= root)
            root = parent(root)
        end do
        j = i
        do while (parent(j) /= root)          ! path compression
            next = parent(j)
            parent(j) = root
            j = next
        end do
    end function find_root

    subroutine unite(parent, i, j)
        integer(i4), intent(inout) :: parent(:)
        integer(i4), intent(in) :: i, j
        integer(i4) :: ri, rj
        ri = find_root(parent, i)
        rj = find_root(parent, j)
        if (ri < rj) then
            parent(rj) = ri
        else if (rj < ri) then
            parent(ri) = rj
        end if
    end subroutine unite

    !> The nodes and body cells of body b.
    subroutine body_members(s, map, body_of_node, b, nodes, cells)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: body_of_node(:), b
        integer(i4), allocatable, intent(out) :: nodes(:), cells(:)
        integer(i4) :: k, c, n
        nodes = pack([(k, k = 1, s%mesh%n_nodes)], body_of_node == b)
        n = 0
        allocate (cells(size(map%cells)))
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (.not. is_body_cell(s, c)) cycle
            if (body_of_node(s%mesh%cell_nodes(s%mesh%cell_ptr(c))) /= b) cycle
            n = n + 1
            cells(n) = c
        end do
        cells = cells(1:n)
    end subroutine body_members

    !> The modes of one body left free by its imposed equations and its linear relations
    !> (body_rows), with their anchors (none: the body is held), and its .mess description.
    subroutine body_modes(s, map, nodes, cells, body_of_node, b, body_rows, found, line, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: nodes(:), cells(:)
        integer(i4), intent(in) :: body_of_node(:), b, body_rows(:)
        type(body_modes_t), intent(out) :: found
        character(len=:), allocatable, intent(out) :: line
        type(status_t), intent(out) :: st
        type(motion_t) :: motions(MAX_BODY_MODES)
        real(dp) :: xc(3), size_body, held(MAX_BODY_MODES, MAX_BODY_MODES), v(MAX_BODY_MODES)
        real(dp), allocatable :: free_dirs(:, :), rows(:, :), free_rows(:, :)
        integer(i4) :: n0, k, i, e, m
        xc = sum(s%mesh%coords(:, nodes), dim=2) / real(size(nodes), dp)
        size_body = 0.0_dp
        do i = 1, size(nodes)
            size_body = max(size_body, norm2(s%mesh%coords(:, nodes(i)) - xc))
        end do
        if (.not. size_body > 0.0_dp) size_body = 1.0_dp
        call candidate_motions(s, cells, xc, motions, n0)
        allocate (found%anchors(0))
        line = ''
        if (n0 == 0) return
        ! the body's equations, and what each candidate motion (unit size) does there
        found%eqs = body_equations(s, nodes)
        allocate (rows(size(found%eqs), n0))
        call advise_huge_pages(rows)
        do i = 1, size(found%eqs)
            e = found%eqs(i)
            do k = 1, n0
                rows(i, k) = motion_value(motions(k), s%mesh%coords(:, &
                    s%dofs%equation_node(e)) - xc, s%dofs%equation_component(e), size_body)
            end do
        end do
        held = 0.0_dp
        do i = 1, size(found%eqs)
            if (.not. map%imposed(found%eqs(i))) cycle
            v(1:n0) = rows(i, :)
            do k = 1, n0
                held(1:n0, k) = held(1:n0, k) + v(1:n0) * v(k)
            end do
        end do
        call add_relation_rows(s, map, body_of_node, b, body_rows, motions(1:n0), xc, &
            size_body, held(1:n0, 1:n0))
        call null_directions(held(1:n0, 1:n0), free_dirs)
        m = size(free_dirs, 2, kind=i4)
        if (m == 0) return
        allocate (free_rows(size(found%eqs), m))
        call advise_huge_pages(free_rows)
        free_rows = matmul(rows, free_dirs)
        deallocate (rows)
        call move_alloc(free_rows, rows)
        call choose_anchors(s, map, found%eqs, rows, found%anchors, st)
        if (st%failed()) return
        call modes_on_anchors(found%eqs, rows, found%anchors, found%values, st)
        if (st%failed()) return
        line = body_text(s, nodes, cells, found%anchors, m, n0)
    end subroutine body_modes

    !> The linear relations on each body's equations (CSR over bodies, each row once per
    !> body it touches; none without relations).
    subroutine relations_of_bodies(s, map, body_of_node, n_bodies, ptr, rows)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: body_of_node(:), n_bodies
        integer(i4), allocatable, intent(out) :: ptr(:), rows(:)
        integer(i4), allocatable :: bodies(:), count_of(:)
        integer(i4) :: r, k, b, n, pass, i
        allocate (ptr(n_bodies + 1), count_of(n_bodies), rows(0))
        ptr = 1
        if (.not. allocated(map%elim%rows%ptr)) return
        do pass = 1, 2
            count_of = 0
            do r = 1, map%elim%rows%n
                if (map%elim%rows%dropped(r)) cycle
                bodies = [(body_of_node(s%dofs%equation_node(map%elim%rows%eq(k))), &
                    k = map%elim%rows%ptr(r), map%elim%rows%ptr(r + 1) - 1)]
                do i = 1, size(bodies)
                    b = bodies(i)
                    if (b == 0) cycle
                    if (any(bodies(1:i - 1) == b)) cycle
                    count_of(b) = count_of(b) + 1
                    if (pass == 2) rows(ptr(b) + count_of(b) - 1) = r
                end do
            end do
            if (pass == 2) exit
            do b = 1, n_bodies
                ptr(b + 1) = ptr(b) + count_of(b)
            end do
            n = ptr(n_bodies + 1) - 1
            deallocate (rows)
            allocate (rows(n))
        end do
    end subroutine relations_of_bodies

    !> held <- held + v v^T for each linear relation `rows` on body b: v the relation
    !> (coefficients of unit norm) applied to the candidate motions (zero off the body). A
    !> mode must satisfy the relations (C R = 0) to be one of the reduced system's
    !> (T R_free = R, assembly_relations); a relation linking two bodies holds each.
    subroutine add_relation_rows(s, map, body_of_node, b, rows, motions, xc, size_body, held)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: body_of_node(:), b, rows(:)
        type(motion_t), intent(in) :: motions(:)
        real(dp), intent(in) :: xc(3), size_body
        real(dp), intent(inout) :: held(:, :)
        real(dp) :: v(size(held, 1)), scale
        integer(i4) :: i, r, k, e, m
        do i = 1, size(rows)
            r = rows(i)
            v = 0.0_dp
            scale = 0.0_dp
            do k = map%elim%rows%ptr(r), map%elim%rows%ptr(r + 1) - 1
                scale = scale + map%elim%rows%coef(k)**2
                e = map%elim%rows%eq(k)
                if (body_of_node(s%dofs%equation_node(e)) /= b) cycle
                do m = 1, size(v, kind=i4)
                    v(m) = v(m) + map%elim%rows%coef(k) * motion_value(motions(m), &
                        s%mesh%coords(:, s%dofs%equation_node(e)) - xc, &
                        s%dofs%equation_component(e), size_body)
                end do
            end do
            if (.not. scale > 0.0_dp) cycle
            v = v / sqrt(scale)
            do m = 1, size(v, kind=i4)
                held(:, m) = held(:, m) + v * v(m)
            end do
        end do
    end subroutine add_relation_rows

    !> The candidate rigid motions of a body (module header): plates or plane solids.
    subroutine candidate_motions(s, cells, xc, motions, n)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: cells(:)
        real(dp), intent(in) :: xc(3)
        type(motion_t), intent(out) :: motions(MAX_BODY_MODES)
        integer(i4), intent(out) :: n
        real(dp) :: normals(3, 3), normal(3), first(3), eig(3), vec(3, 3)
        logical :: plate, plane, warped, flat
        integer(i4) :: k, c
        plate = all(is_plate(s%model%element(cells)))
        plane = all(is_plane_solid(s%model%element(cells)))
        n = 0
        if (plane) then
            motions(1) = motion_t(.false., .false., [1.0_dp, 0.0_dp, 0.0_dp])
            motions(2) = motion_t(.false., .false., [0.0_dp, 1.0_dp, 0.0_dp])
            motions(3) = motion_t(.true., .false., [0.0_dp, 0.0_dp, 1.0_dp])
            n = 3
            return
        end if
        if (.not. plate) return
        do k = 1, 3
            motions(k)%axis = 0.0_dp
            motions(k)%axis(k) = 1.0_dp
        end do
        n = 3
        normals = 0.0_dp
        warped = .false.
        flat = .true.
        first = 0.0_dp
        do k = 1, size(cells)
            c = cells(k)
            call cell_normal(s, c, normal, warped)
            if (warped) exit
            if (k == 1) first = normal
            if (norm2(cross(first, normal)) > PARALLEL_TOLERANCE) flat = .false.
            normals = normals + outer(normal, normal)
        end do
        if (warped) return
        if (flat) flat = body_in_plane(s, cells, xc, first)
        call symmetric_eigen(normals, eig, vec)
        do k = 1, 3
            ! axes normal to every cell normal: no energy in the plates (module header)
            if (eig(k) > PARALLEL_TOLERANCE * real(size(cells), dp)) cycle
            n = n + 1
            motions(n) = motion_t(.true., .true., vec(:, k))
        end do
        if (flat) then
            n = n + 1
            motions(n) = motion_t(.true., .false., first)
        end if
    end subroutine candidate_motions

    !> The unit normal of a plate cell (as the element's mean plane: QUAD4 by its
    !> diagonals), and whether the cell is warped (a node off that plane).
    subroutine cell_normal(s, c, normal, warped)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        real(dp), intent(out) :: normal(3)
        logical, intent(inout) :: warped
        real(dp) :: x(3, 4), centre(3), extent
        integer(i4) :: nn, p0, i
        p0 = s%mesh%cell_ptr(c)
        nn = min(s%mesh%cell_ptr(c + 1) - p0, 4_i4)
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        if (nn == 4) then
            normal = cross(x(:, 3) - x(:, 1), x(:, 4) - x(:, 2))
        else
            normal = cross(x(:, 2) - x(:, 1), x(:, 3) - x(:, 1))
        end if
        if (.not. norm2(normal) > 0.0_dp) then
            warped = .true.
            return
        end if
        normal = normal / norm2(normal)
        centre = sum(x(:, 1:nn), dim=2) / real(nn, dp)
        extent = 0.0_dp
        do i = 1, nn
            extent = max(extent, norm2(x(:, i) - centre))
        end do
        do i = 1, nn
            if (abs(dot_product(x(:, i) - centre, normal)) > FLAT_TOLERANCE * extent) &
                warped = .true.
        end do
    end subroutine cell_normal

    !> Whether every node of the body's cells lies in the plane through xc normal to n.
    logical function body_in_plane(s, cells, xc, n) result(inside)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: cells(:)
        real(dp), intent(in) :: xc(3), n(3)
        real(dp) :: extent
        integer(i4) :: k, p
        extent = 0.0_dp
        do k = 1, size(cells)
            do p = s%mesh%cell_ptr(cells(k)), s%mesh%cell_ptr(cells(k) + 1) - 1
                extent = max(extent, norm2(s%mesh%coords(:, s%mesh%cell_nodes(p)) - xc))
            end do
        end do
        inside = .true.
        do k = 1, size(cells)
            do p = s%mesh%cell_ptr(cells(k)), s%mesh%cell_ptr(cells(k) + 1) - 1
                if (abs(dot_product(s%mesh%coords(:, s%mesh%cell_nodes(p)) - xc, n)) > &
                    FLAT_TOLERANCE * extent) inside = .false.
            end do
        end do
    end function body_in_plane

    !> Every equation of the body's nodes (free and imposed), node by node.
    function body_equations(s, nodes) result(eqs)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: nodes(:)
        integer(i4), allocatable :: eqs(:)
        integer(i4) :: i, k, n
        allocate (eqs(N_COMPONENTS * size(nodes)))
        n = 0
        do i = 1, size(nodes)
            do k = 1, N_COMPONENTS
                if (s%dofs%equation(k, nodes(i)) == 0) cycle
                n = n + 1
                eqs(n) = s%dofs%equation(k, nodes(i))
            end do
        end do
        eqs = eqs(1:n)
    end function body_equations

    !> The value of motion `mo` (unit translation, or unit rotation scaled by 1 / size so
    !> that its terms are at most ~1) on component `comp` of a node at arm d from xc.
    pure real(dp) function motion_value(mo, d, comp, size_body) result(v)
        type(motion_t), intent(in) :: mo
        real(dp), intent(in) :: d(3), size_body
        integer(i4), intent(in) :: comp
        real(dp) :: u(3)
        v = 0.0_dp
        if (.not. mo%rotation) then
            if (comp <= 3) v = mo%axis(comp)
            return
        end if
        if (comp <= 3) then
            u = cross(mo%axis, d)
            v = u(comp) / size_body
        else if (mo%rotate_dofs) then
            v = mo%axis(comp - 3) / size_body
        end if
    end function motion_value

    !> The directions (columns of an orthonormal basis) along which the quadratic form
    !> `held` (constraint energy of combinations of the candidates) is zero to round-off.
    subroutine null_directions(held, dirs)
        real(dp), intent(in) :: held(:, :)
        real(dp), allocatable, intent(out) :: dirs(:, :)
        real(dp) :: eig(size(held, 1)), vec(size(held, 1), size(held, 1)), top
        integer(i4) :: k, n
        n = size(held, 1, kind=i4)
        call symmetric_eigen(held, eig, vec)
        top = max(maxval(abs(eig)), 1.0_dp)
        allocate (dirs(n, 0))
        do k = 1, n
            if (abs(eig(k)) <= HELD_TOLERANCE * top) dirs = reshape([dirs, vec(:, k)], &
                [n, size(dirs, 2) + 1])
        end do
    end subroutine null_directions

    !> One anchor per mode: pivoted Gram-Schmidt on the rows of the modes at the body's
    !> free translations (then any free equation if those do not span the modes); the
    !> first row of largest remaining norm is taken, so the choice is deterministic.
    subroutine choose_anchors(s, map, eqs, rows, anchors, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: eqs(:)
        real(dp), intent(in) :: rows(:, :)
        integer(i4), allocatable, intent(out) :: anchors(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: rest(:, :)
        integer(i4), allocatable :: candidates(:)
        real(dp) :: q(size(rows, 2)), top, norm2_best, norm2_i
        integer(i4) :: m, k, i, best, pass
        m = size(rows, 2, kind=i4)
        allocate (anchors(m))
        top = maxval(abs(rows))
        do pass = 1, 2
            ! the rows that may be anchors (free; translations first), copied once
            if (pass == 1) then
                candidates = pack([(i, i = 1, size(eqs, kind=i4))], map%free_eq(eqs) > 0 &
                    .and. s%dofs%equation_component(eqs) <= DOF_DZ)
            else
                candidates = pack([(i, i = 1, size(eqs, kind=i4))], map%free_eq(eqs) > 0)
            end if
            rest = rows(candidates, :)
            do k = 1, m
                best = 0
                norm2_best = (1.0e3_dp * epsilon(1.0_dp) * top)**2
                do i = 1, size(rest, 1, kind=i4)
                    norm2_i = sum(rest(i, :)**2)
                    if (norm2_i > norm2_best) then
                        best = i
                        norm2_best = norm2_i
                    end if
                end do
                if (best == 0) exit
                anchors(k) = candidates(best)
                q = rest(best, :) / sqrt(norm2_best)
                do i = 1, size(rest, 1, kind=i4)
                    rest(i, :) = rest(i, :) - dot_product(rest(i, :), q) * q
                end do
                rest(best, :) = 0.0_dp
            end do
            if (k > m) then
                anchors = eqs(anchors)
                return
            end if
        end do
        call set_error(st, STATUS_INTERNAL, 'rigid modes: no anchor equations for ' // &
            to_text(m) // ' modes')
    end subroutine choose_anchors

    !> The modes recombined so that mode k is 1 on anchor k and 0 on the other anchors
    !> (R (R_A)^-1, Gauss-Jordan with partial pivoting on the m x m R_A); the anchor rows
    !> are set to the identity exactly.
    subroutine modes_on_anchors(eqs, rows, anchors, values, st)
        integer(i4), intent(in) :: eqs(:), anchors(:)
        real(dp), intent(in) :: rows(:, :)
        real(dp), allocatable, intent(out) :: values(:, :)
        type(status_t), intent(out) :: st
        real(dp) :: ra(size(anchors), size(anchors)), inv(size(anchors), size(anchors))
        integer(i4) :: m, k, i
        m = size(anchors, kind=i4)
        do k = 1, m
            ra(k, :) = rows(findloc(eqs, anchors(k), dim=1), :)
        end do
        call invert(ra, inv, st)
        if (st%failed()) return
        allocate (values(size(rows, 1), m))
        call advise_huge_pages(values)
        values = matmul(rows, inv)
        do k = 1, m
            i = findloc(eqs, anchors(k), dim=1)
            values(i, :) = 0.0_dp
            values(i, k) = 1.0_dp
        end do
    end subroutine modes_on_anchors

    !> inv = a^-1 by Gauss-Jordan with partial pivoting (a small, well conditioned by the
    !> choice of the anchors).
    subroutine invert(a, inv, st)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: inv(:, :)
        type(status_t), intent(out) :: st
        real(dp) :: w(size(a, 1), 2 * size(a, 1)), row(2 * size(a, 1))
        integer(i4) :: n, i, j, p
        n = size(a, 1, kind=i4)
        w = 0.0_dp
        w(:, 1:n) = a
        do i = 1, n
            w(i, n + i) = 1.0_dp
        end do
        do j = 1, n
            p = j - 1 + int(maxloc(abs(w(j:n, j)), dim=1), i4)
            if (.not. abs(w(p, j)) > 0.0_dp) then
                call set_error(st, STATUS_INTERNAL, 'rigid modes: singular anchor matrix')
                return
            end if
            row = w(p, :)
            w(p, :) = w(j, :)
            w(j, :) = row / row(j)
            do i = 1, n
                if (i /= j) w(i, :) = w(i, :) - w(i, j) * w(j, :)
            end do
        end do
        inv = w(:, n + 1:2 * n)
    end subroutine invert

    !> "body of cell M1 (4096 DKQ/DKT cells, 4225 nodes): held only by springs: 6 rigid
    !> modes of 6 kept apart, anchored at node N1 component DZ, ..."
    function body_text(s, nodes, cells, anchors, m, n0) result(text)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: nodes(:), cells(:), anchors(:), m, n0
        character(len=:), allocatable :: text
        integer(i4) :: k
        text = 'body of cell ' // cell_name(s%mesh, cells(1)) // ' (' // &
            to_text(size(cells)) // ' cells, ' // to_text(size(nodes)) // ' nodes): ' // &
            to_text(m) // ' of its ' // to_text(n0) // ' rigid modes held only by ' // &
            'springs, kept apart (anchors'
        do k = 1, size(anchors)
            if (k > 1) text = text // ','
            text = text // ' ' // describe_equation(s%dofs, s%mesh, anchors(k))
        end do
        text = text // ')'
    end function body_text

    !> Eigenvalues (ascending) and orthonormal eigenvectors of a small symmetric matrix
    !> (cyclic Jacobi rotations, Golub & Van Loan 8.5).
    pure subroutine symmetric_eigen(a, eig, vec)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(out) :: eig(:), vec(:, :)
        real(dp) :: w(size(a, 1), size(a, 1)), theta, t, c, sn, tmp(size(a, 1)), off, h
        integer(i4) :: n, p, q, sweep, k
        n = size(a, 1, kind=i4)
        w = a
        vec = 0.0_dp
        do p = 1, n
            vec(p, p) = 1.0_dp
        end do
        do sweep = 1, 60
            off = 0.0_dp
            do p = 1, n - 1
                do q = p + 1, n
                    off = off + w(p, q)**2
                end do
            end do
            if (.not. off > 0.0_dp) exit
            do p = 1, n - 1
                do q = p + 1, n
                    ! a term at round-off level of its diagonal, or subnormal, is zero
                    if (abs(w(p, q)) <= epsilon(1.0_dp)**2 * (abs(w(p, p)) + abs(w(q, q))) &
                        .or. abs(w(p, q)) < tiny(1.0_dp)) then
                        w(p, q) = 0.0_dp
                        w(q, p) = 0.0_dp
                        cycle
                    end if
                    h = w(q, q) - w(p, p)
                    if (abs(w(p, q)) <= epsilon(1.0_dp) * abs(h)) then
                        t = w(p, q) / h          ! theta^2 would overflow: t ~ 1 / (2 theta)
                    else
                        theta = 0.5_dp * h / w(p, q)
                        t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta**2 + 1.0_dp))
                    end if
                    c = 1.0_dp / sqrt(t**2 + 1.0_dp)
                    sn = t * c
                    tmp = w(:, p)
                    w(:, p) = c * tmp - sn * w(:, q)
                    w(:, q) = sn * tmp + c * w(:, q)
                    tmp = w(p, :)
                    w(p, :) = c * tmp - sn * w(q, :)
                    w(q, :) = sn * tmp + c * w(q, :)
                    tmp = vec(:, p)
                    vec(:, p) = c * tmp - sn * vec(:, q)
                    vec(:, q) = sn * tmp + c * vec(:, q)
                end do
            end do
        end do
        do k = 1, n
            eig(k) = w(k, k)
        end do
        ! ascending order (selection sort: n <= 6)
        do p = 1, n - 1
            q = p - 1 + int(minloc(eig(p:n), dim=1), i4)
            if (q == p) cycle
            t = eig(p)
            eig(p) = eig(q)
            eig(q) = t
            tmp = vec(:, p)
            vec(:, p) = vec(:, q)
            vec(:, q) = tmp
        end do
    end subroutine symmetric_eigen

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    pure function outer(a, b) result(m)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: m(3, 3)
        integer(i4) :: j
        do j = 1, 3
            m(:, j) = a * b(j)
        end do
    end function outer

end module rigid_bodies
