!> Geometry of the linear relations of AFFE_CHAR_MECA (Code_Aster U4.44.01): the normal
!> or tangent at the nodes of a face (FACE_IMPO DNOR/DTAN/DRNOR, ARETE_IMPO DTAN,
!> LIAISON_GROUP DNOR), the frame of nautical angles (LIAISON_OBLIQUE, LIAISON_GROUP), the
!> rigid-body relations of LIAISON_SOLIDE, the weights of LIAISON_RBE3 and the pairs of
!> nodes of LIAISON_GROUP. Relations come out as lists of terms (node, component,
!> coefficient); relation_commands turns them into load items.
module model_relations
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use mesh_types, only: mesh_t, node_name, cell_name
    use mesh_cell_shapes, only: cell_shape, cell_reference_nodes, CELL_TYPE_NODES, &
        CELL_TYPE_DIM, MAX_CELL_NODES
    use model_dof_numbering, only: dof_numbering_t, DOF_DX, DOF_DY, DOF_DZ, DOF_DRX, &
        DOF_DRY, DOF_DRZ
    implicit none
    private

    !> A node's averaged normal shorter than this (the cells' unit normals cancel) has no
    !> direction (Code_Aster canort, message CHARGES2_30).
    real(dp), parameter :: SHORT_NORMAL = 1.0e-2_dp
    !> Code_Aster's default LIAISON_SOLIDE/DIST_MIN: this fraction of the mesh's shortest
    !> edge (caliso: 1e-3 armin).
    real(dp), parameter, public :: DIST_MIN_FRACTION = 1.0e-3_dp

    !> Relations as lists of terms: relation r is terms ptr(r) .. ptr(r+1)-1.
    type, public :: relation_list_t
        integer(i4) :: n = 0
        integer(i4), allocatable :: ptr(:), node(:), comp(:)
        real(dp), allocatable :: coef(:)
    end type relation_list_t

    public :: node_directions, nautical_frame, rigid_body_relations, rbe3_coefficients, &
        pair_nodes, relation_add, shortest_edge

contains

    !> The unit normal (or tangent) of a face at each of its nodes: the mean of the unit
    !> normals of the face's cells at the node, normalised (Code_Aster canort). In a 2D mesh
    !> the cells are lines, the normal (t_y, -t_x) of the tangent t from the cell's first
    !> node to its second; in 3D they are surfaces (normal x_xi ^ x_eta, by the right-hand
    !> rule on the node order), or lines for a tangent.
    !>  cells   : in, the face's cells
    !>  nodes   : in, the nodes wanted (each on some cell)
    !>  tangent : in, .true. for the tangent (lines only), .false. for the normal
    !>  vectors : out, vectors(1:3, size(nodes)) (z = 0 in 2D)
    !>  st      : out, STATUS_MODEL_ERROR: a cell of the wrong dimension, a degenerate cell,
    !>            normals that cancel at a node, a node on none of the cells
    subroutine node_directions(mesh, cells, nodes, tangent, vectors, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), nodes(:)
        logical, intent(in) :: tangent
        real(dp), intent(out) :: vectors(3, size(nodes))
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: slot(:)
        integer(i4) :: k, c, p0, nn, i, ctype, wanted_dim, n
        real(dp) :: xi(2, MAX_CELL_NODES), x(3, MAX_CELL_NODES), v(3), norm
        allocate (slot(mesh%n_nodes), source=0_i4)
        do k = 1, size(nodes)
            slot(nodes(k)) = k
        end do
        vectors = 0.0_dp
        wanted_dim = mesh%dim - 1
        if (tangent) wanted_dim = 1
        do k = 1, size(cells)
            c = cells(k)
            ctype = mesh%cell_type(c)
            if (CELL_TYPE_DIM(ctype) /= wanted_dim) then
                call set_error(st, STATUS_MODEL_ERROR, 'cell ' // cell_name(mesh, c) // &
                    ' is not a ' // trim(merge('line   ', 'surface', wanted_dim == 1)) // &
                    ': in a ' // to_text(mesh%dim) // 'D mesh the ' // &
                    trim(merge('tangent', 'normal ', tangent)) // ' is taken on ' // &
                    trim(merge('lines   ', 'surfaces', wanted_dim == 1)))
                return
            end if
            p0 = mesh%cell_ptr(c)
            nn = CELL_TYPE_NODES(ctype)
            x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(p0:p0 + nn - 1))
            call cell_reference_nodes(ctype, xi)
            do i = 1, nn
                n = slot(mesh%cell_nodes(p0 + i - 1))
                if (n == 0) cycle
                call cell_direction(ctype, nn, x, xi(:, i), tangent, mesh%dim, v)
                norm = norm2(v)
                if (.not. norm > 0.0_dp) then
                    call set_error(st, STATUS_MODEL_ERROR, 'cell ' // cell_name(mesh, c) // &
                        ' is degenerate at node ' // node_name(mesh, mesh%cell_nodes(p0 + i &
                        - 1)) // ': it has no ' // trim(merge('tangent', 'normal ', tangent)))
                    return
                end if
                vectors(:, n) = vectors(:, n) + v / norm
            end do
        end do
        do k = 1, size(nodes)
            norm = norm2(vectors(:, k))
            if (norm < SHORT_NORMAL) then
                call set_error(st, STATUS_MODEL_ERROR, 'at node ' // node_name(mesh, &
                    nodes(k)) // ' the ' // trim(merge('tangents', 'normals ', tangent)) // &
                    ' of the cells ' // trim(merge('cancel      ', 'do not reach', &
                    norm > 0.0_dp)) // ' it: no direction there (Code_Aster CHARGES2_30)')
                return
            end if
            vectors(:, k) = vectors(:, k) / norm
        end do
    end subroutine node_directions

    ! The tangent of a line cell, or the normal of a line (2D) or surface (3D) cell, at
    ! reference point xi (not normalised).
    pure subroutine cell_direction(ctype, nn, x, xi, tangent, dim, v)
        integer(i4), intent(in) :: ctype, nn, dim
        real(dp), intent(in) :: x(3, MAX_CELL_NODES), xi(2)
        logical, intent(in) :: tangent
        real(dp), intent(out) :: v(3)
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), a(3), b(3)
        call cell_shape(ctype, xi(1), xi(2), n, dn)
        a = matmul(x(:, 1:nn), dn(1, 1:nn))
        if (tangent) then
            v = a
        else if (dim == 2) then
            v = [a(2), -a(1), 0.0_dp]
        else
            b = matmul(x(:, 1:nn), dn(2, 1:nn))
            v = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
        end if
    end subroutine cell_direction

    !> The frame of Code_Aster's nautical angles (alpha about Z, then beta about the new Y,
    !> then gamma about the new X; R4.01.01): rows are the frame's axes in global
    !> components, u_frame = p u_global.
    !>  degrees : in, 1 to 3 angles in degrees (the missing ones 0)
    pure subroutine nautical_frame(degrees, p)
        real(dp), intent(in) :: degrees(:)
        real(dp), intent(out) :: p(3, 3)
        real(dp) :: a(3), ca, sa, cb, sb, cg, sg
        real(dp), parameter :: PI = 3.14159265358979323846_dp
        a = 0.0_dp
        a(1:min(3, size(degrees))) = degrees(1:min(3, size(degrees))) * PI / 180.0_dp
        ca = cos(a(1)); sa = sin(a(1))
        cb = cos(a(2)); sb = sin(a(2))
        cg = cos(a(3)); sg = sin(a(3))
        p(1, :) = [cb * ca, cb * sa, -sb]
        p(2, :) = [sg * sb * ca - cg * sa, cg * ca + sg * sb * sa, sg * cb]
        p(3, :) = [sg * sa + cg * sb * ca, cg * sb * sa - ca * sg, cg * cb]
    end subroutine nautical_frame

    !> Appends one relation (terms) to a list.
    subroutine relation_add(list, nodes, comps, coefs)
        type(relation_list_t), intent(inout) :: list
        integer(i4), intent(in) :: nodes(:), comps(:)
        real(dp), intent(in) :: coefs(:)
        integer(i4) :: m
        if (.not. allocated(list%ptr)) then
            allocate (list%ptr(1), list%node(0), list%comp(0), list%coef(0))
            list%ptr(1) = 1
        end if
        m = list%ptr(list%n + 1)
        list%node = [list%node, nodes]
        list%comp = [list%comp, comps]
        list%coef = [list%coef, coefs]
        list%ptr = [list%ptr, m + size(nodes, kind=i4)]
        list%n = list%n + 1
    end subroutine relation_add

    !> The mesh's shortest cell edge (Code_Aster armin): the distance between consecutive
    !> corners of its line and surface cells; 0 for a mesh without any.
    pure real(dp) function shortest_edge(mesh) result(d)
        type(mesh_t), intent(in) :: mesh
        integer(i4) :: c, p0, nc, i, a, b
        real(dp) :: e
        d = huge(1.0_dp)
        do c = 1, mesh%n_cells
            p0 = mesh%cell_ptr(c)
            nc = mesh%cell_ptr(c + 1) - p0
            if (nc < 2) cycle
            if (CELL_TYPE_DIM(mesh%cell_type(c)) == 1) nc = 2
            if (CELL_TYPE_DIM(mesh%cell_type(c)) == 2) nc = min(nc, 4_i4)
            if (mesh%cell_type(c) > 0 .and. CELL_TYPE_NODES(mesh%cell_type(c)) == 6) nc = 3
            do i = 1, nc
                a = mesh%cell_nodes(p0 + i - 1)
                b = mesh%cell_nodes(p0 + modulo(i, nc))
                e = norm2(mesh%coords(:, a) - mesh%coords(:, b))
                if (e > 0.0_dp) d = min(d, e)
            end do
        end do
        if (.not. d < huge(1.0_dp)) d = 0.0_dp
    end function shortest_edge

    !> LIAISON_SOLIDE (Code_Aster caliso): the relations that keep a set of nodes rigid
    !> (small displacements). With a node that has the three rotations (two in 2D: DRZ), A
    !> the first such node: u_M = u_A + theta_A ^ AM and theta_M = theta_A for every other
    !> node M (the components M has; Code_Aster drz13d). Otherwise (translations only) the
    !> rigid motion u = u_A + omega ^ (x - x_A) is spanned by reference nodes: A the first
    !> node, B the farthest from A, C (3D) the farthest from line AB; the relations keep
    !> AB (and AC, the angle) and give every other node the motion omega of A, B (and C).
    !> Points closer than dist_min count as one (Code_Aster DIST_MIN).
    !>  nodes : in, the body's nodes (at least 2)
    !>  list  : out, the relations
    !>  st    : out, a node with no displacement component
    subroutine rigid_body_relations(mesh, dofs, nodes, dist_min, list, st)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: nodes(:)
        real(dp), intent(in) :: dist_min
        type(relation_list_t), intent(out) :: list
        type(status_t), intent(out) :: st
        integer(i4) :: k, a
        allocate (list%ptr(1), list%node(0), list%comp(0), list%coef(0))
        list%ptr(1) = 1
        do k = 1, size(nodes)
            if (all(dofs%equation(DOF_DX:DOF_DZ, nodes(k)) == 0)) then
                call set_error(st, STATUS_MODEL_ERROR, 'node ' // node_name(mesh, nodes(k)) &
                    // ' has no displacement component in the model: no element carries it')
                return
            end if
        end do
        a = 0
        do k = 1, size(nodes)
            if (has_rotations(mesh, dofs, nodes(k))) then
                a = nodes(k)
                exit
            end if
        end do
        if (a > 0) then
            call rotation_body(mesh, dofs, nodes, a, list)
        else if (mesh%dim == 2) then
            call translation_body_2d(mesh, dofs, nodes, dist_min, list)
        else
            call translation_body_3d(mesh, dofs, nodes, dist_min, list)
        end if
    end subroutine rigid_body_relations

    ! The node has the rotations (DRX DRY DRZ in 3D, DRZ in 2D).
    pure logical function has_rotations(mesh, dofs, node)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: node
        if (mesh%dim == 2) then
            has_rotations = dofs%equation(DOF_DRZ, node) > 0
        else
            has_rotations = all(dofs%equation(DOF_DRX:DOF_DRZ, node) > 0)
        end if
    end function has_rotations

    ! u_M = u_A + theta_A ^ AM, theta_M = theta_A (components M has).
    subroutine rotation_body(mesh, dofs, nodes, a, list)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: nodes(:), a
        type(relation_list_t), intent(inout) :: list
        integer(i4) :: k, m, i
        real(dp) :: r(3)
        ! (theta ^ r)_x = th_y r_z - th_z r_y, _y = th_z r_x - th_x r_z, _z = th_x r_y - th_y r_x
        integer(i4), parameter :: ROT1(3) = [DOF_DRY, DOF_DRZ, DOF_DRX]
        integer(i4), parameter :: ROT2(3) = [DOF_DRZ, DOF_DRX, DOF_DRY]
        integer(i4), parameter :: ARM1(3) = [3, 1, 2], ARM2(3) = [2, 3, 1]
        do k = 1, size(nodes)
            m = nodes(k)
            if (m == a) cycle
            r = mesh%coords(:, m) - mesh%coords(:, a)
            do i = 1, 3
                if (dofs%equation(i, m) == 0) cycle
                if (mesh%dim == 2 .and. i == 3) cycle
                if (mesh%dim == 2) then
                    ! u_x = u_Ax - th_z r_y, u_y = u_Ay + th_z r_x
                    call relation_add(list, [m, a, a], [i, i, DOF_DRZ], [1.0_dp, -1.0_dp, &
                        merge(r(2), -r(1), i == 1)])
                else
                    call relation_add(list, [m, a, a, a], [i, i, ROT1(i), ROT2(i)], &
                        [1.0_dp, -1.0_dp, -r(ARM1(i)), r(ARM2(i))])
                end if
            end do
            do i = DOF_DRX, DOF_DRZ
                if (dofs%equation(i, m) == 0 .or. dofs%equation(i, a) == 0) cycle
                call relation_add(list, [m, a], [i, i], [1.0_dp, -1.0_dp])
            end do
        end do
    end subroutine rotation_body

    ! Translations only, 2D: A, B (farthest from A). omega = w . (u_B - u_A) with
    ! w = k ^ AB / |AB|^2; B keeps |AB|: AB . (u_B - u_A) = 0; every other M:
    ! u_M - u_A - (k ^ AM) omega = 0. All points within dist_min of A: u_M = u_A.
    subroutine translation_body_2d(mesh, dofs, nodes, dist_min, list)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: nodes(:)
        real(dp), intent(in) :: dist_min
        type(relation_list_t), intent(inout) :: list
        integer(i4) :: a, b, k, m, i
        real(dp) :: ab(2), w(2), am(2), kam(2), l2
        a = nodes(1)
        b = farthest(mesh, nodes, a)
        ab = mesh%coords(1:2, b) - mesh%coords(1:2, a)
        l2 = dot_product(ab, ab)
        if (.not. sqrt(l2) > dist_min) then
            call same_motion(nodes, a, [1, 2], dofs, list)
            return
        end if
        w = [-ab(2), ab(1)] / l2
        call relation_add(list, [b, b, a, a], [1, 2, 1, 2], [ab(1), ab(2), -ab(1), -ab(2)])
        do k = 1, size(nodes)
            m = nodes(k)
            if (m == a .or. m == b) cycle
            am = mesh%coords(1:2, m) - mesh%coords(1:2, a)
            kam = [-am(2), am(1)]
            do i = 1, 2
                if (dofs%equation(i, m) == 0) cycle
                call relation_add(list, [m, a, a, a, b, b], [i, i, 1, 2, 1, 2], &
                    [1.0_dp, -1.0_dp, kam(i) * w(1), kam(i) * w(2), -kam(i) * w(1), &
                     -kam(i) * w(2)])
            end do
        end do
    end subroutine translation_body_2d

    ! Translations only, 3D: A, B (farthest from A), C (farthest from line AB). With b =
    ! AB, c = AC: b.(u_B-u_A) = 0, c.(u_C-u_A) = 0, c.(u_B-u_A) + b.(u_C-u_A) = 0, and
    ! omega = M^-1 (b ^ d_B + c ^ d_C), M = sum (|r|^2 I - r r^T), d = u - u_A, for the
    ! others: u_M - u_A - omega ^ AM = 0. Collinear (C within dist_min of line AB):
    ! omega = b ^ d_B / |b|^2 and only B's relation. All within dist_min: u_M = u_A.
    subroutine translation_body_3d(mesh, dofs, nodes, dist_min, list)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: nodes(:)
        real(dp), intent(in) :: dist_min
        type(relation_list_t), intent(inout) :: list
        integer(i4) :: a, b, c, k, m, i, j
        real(dp) :: bv(3), cv(3), dist_c, mm(3, 3), minv(3, 3), wb(3, 3), wc(3, 3)
        real(dp) :: am(3), g(3, 3)
        logical :: planar
        a = nodes(1)
        b = farthest(mesh, nodes, a)
        bv = mesh%coords(:, b) - mesh%coords(:, a)
        if (.not. norm2(bv) > dist_min) then
            call same_motion(nodes, a, [1, 2, 3], dofs, list)
            return
        end if
        c = farthest_from_line(mesh, nodes, a, bv, dist_c)
        planar = dist_c > dist_min
        cv = 0.0_dp
        if (planar) cv = mesh%coords(:, c) - mesh%coords(:, a)
        call relation_add(list, [b, b, b, a, a, a], [1, 2, 3, 1, 2, 3], [bv, -bv])
        mm = gram(bv)
        if (planar) then
            call relation_add(list, [c, c, c, a, a, a], [1, 2, 3, 1, 2, 3], [cv, -cv])
            call relation_add(list, [b, b, b, c, c, c, a, a, a], [1, 2, 3, 1, 2, 3, 1, 2, 3], &
                [cv, bv, -(bv + cv)])
            mm = mm + gram(cv)
            call invert3(mm, minv)
        else
            ! omega perpendicular to the line: b ^ d_B / |b|^2
            minv = 0.0_dp
            do i = 1, 3
                minv(i, i) = 1.0_dp / dot_product(bv, bv)
            end do
        end if
        wb = matmul(minv, cross_matrix(bv))     ! omega = wb d_B + wc d_C
        wc = matmul(minv, cross_matrix(cv))
        do k = 1, size(nodes)
            m = nodes(k)
            if (m == a .or. m == b .or. (planar .and. m == c)) cycle
            am = mesh%coords(:, m) - mesh%coords(:, a)
            ! (omega ^ am)_i = -([am]x)(i, :) . omega, omega = wb d_B + wc d_C
            do i = 1, 3
                if (dofs%equation(i, m) == 0) cycle
                do j = 1, 3
                    g(j, 1) = dot_product(-cross_matrix_row(am, i), wb(:, j))
                    g(j, 2) = dot_product(-cross_matrix_row(am, i), wc(:, j))
                end do
                ! u_M,i - u_A,i - sum_j G_bj (u_Bj - u_Aj) - sum_j G_cj (u_Cj - u_Aj) = 0
                if (planar) then
                    call relation_add(list, [m, a, b, b, b, c, c, c, a, a, a], &
                        [i, i, 1, 2, 3, 1, 2, 3, 1, 2, 3], &
                        [1.0_dp, -1.0_dp, -g(:, 1), -g(:, 2), g(:, 1) + g(:, 2)])
                else
                    call relation_add(list, [m, a, b, b, b, a, a, a], [i, i, 1, 2, 3, 1, 2, 3], &
                        [1.0_dp, -1.0_dp, -g(:, 1), g(:, 1)])
                end if
            end do
        end do
    end subroutine translation_body_3d

    ! u_M = u_A, components `comps`, for every node M /= A that has them.
    subroutine same_motion(nodes, a, comps, dofs, list)
        integer(i4), intent(in) :: nodes(:), a, comps(:)
        type(dof_numbering_t), intent(in) :: dofs
        type(relation_list_t), intent(inout) :: list
        integer(i4) :: k, i
        do k = 1, size(nodes)
            if (nodes(k) == a) cycle
            do i = 1, size(comps)
                if (dofs%equation(comps(i), nodes(k)) == 0) cycle
                call relation_add(list, [nodes(k), a], [comps(i), comps(i)], &
                    [1.0_dp, -1.0_dp])
            end do
        end do
    end subroutine same_motion

    ! The node of `nodes` farthest from node a (the first of equals).
    pure integer(i4) function farthest(mesh, nodes, a) result(b)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: nodes(:), a
        integer(i4) :: k
        real(dp) :: d, best
        b = a
        best = -1.0_dp
        do k = 1, size(nodes)
            d = norm2(mesh%coords(:, nodes(k)) - mesh%coords(:, a))
            if (d > best) then
                best = d
                b = nodes(k)
            end if
        end do
    end function farthest

    ! The node of `nodes` farthest from the line through node a along v, and its distance.
    integer(i4) function farthest_from_line(mesh, nodes, a, v, dist) result(c)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: nodes(:), a
        real(dp), intent(in) :: v(3)
        real(dp), intent(out) :: dist
        integer(i4) :: k
        real(dp) :: r(3), e(3), d
        e = v / norm2(v)
        c = a
        dist = -1.0_dp
        do k = 1, size(nodes)
            r = mesh%coords(:, nodes(k)) - mesh%coords(:, a)
            d = norm2(r - dot_product(r, e) * e)
            if (d > dist) then
                dist = d
                c = nodes(k)
            end if
        end do
    end function farthest_from_line

    ! |r|^2 I - r r^T
    pure function gram(r) result(m)
        real(dp), intent(in) :: r(3)
        real(dp) :: m(3, 3)
        integer :: i
        m = -spread(r, 2, 3) * spread(r, 1, 3)
        do i = 1, 3
            m(i, i) = m(i, i) + dot_product(r, r)
        end do
    end function gram

    ! [r]x: [r]x v = r ^ v
    pure function cross_matrix(r) result(m)
        real(dp), intent(in) :: r(3)
        real(dp) :: m(3, 3)
        m(1, :) = [0.0_dp, -r(3), r(2)]
        m(2, :) = [r(3), 0.0_dp, -r(1)]
        m(3, :) = [-r(2), r(1), 0.0_dp]
    end function cross_matrix

    pure function cross_matrix_row(r, i) result(row)
        real(dp), intent(in) :: r(3)
        integer(i4), intent(in) :: i
        real(dp) :: row(3), m(3, 3)
        m = cross_matrix(r)
        row = m(i, :)
    end function cross_matrix_row

    ! Inverse of a 3 x 3 matrix by cofactors (the matrix is a positive definite Gram sum).
    pure subroutine invert3(m, inv)
        real(dp), intent(in) :: m(3, 3)
        real(dp), intent(out) :: inv(3, 3)
        real(dp) :: det
        inv(1, 1) = m(2, 2) * m(3, 3) - m(2, 3) * m(3, 2)
        inv(1, 2) = m(1, 3) * m(3, 2) - m(1, 2) * m(3, 3)
        inv(1, 3) = m(1, 2) * m(2, 3) - m(1, 3) * m(2, 2)
        inv(2, 1) = m(2, 3) * m(3, 1) - m(2, 1) * m(3, 3)
        inv(2, 2) = m(1, 1) * m(3, 3) - m(1, 3) * m(3, 1)
        inv(2, 3) = m(1, 3) * m(2, 1) - m(1, 1) * m(2, 3)
        inv(3, 1) = m(2, 1) * m(3, 2) - m(2, 2) * m(3, 1)
        inv(3, 2) = m(1, 2) * m(3, 1) - m(1, 1) * m(3, 2)
        inv(3, 3) = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)
        det = m(1, 1) * inv(1, 1) + m(1, 2) * inv(2, 1) + m(1, 3) * inv(3, 1)
        inv = inv / det
    end subroutine invert3

    !> LIAISON_RBE3 (Code_Aster carbe3; the RBE3 of NASTRAN): the master's motion is the
    !> weighted least-squares rigid motion of the slaves' chosen components. With S (rows:
    !> the slaves' components; columns: the master's DX..DRZ) the rigid map u_i = u_m +
    !> theta_m ^ r_i, theta_i = theta_m (r_i from the master), W the weights (COEF_ESCL for
    !> translations, COEF_ESCL Lc^2 for rotations, Lc the slaves' mean distance to the
    !> master), the coefficients are B = (S^T W S)^-1 S^T W and the master's component k
    !> satisfies u_m(k) = sum_j B(k, j) u_j.
    !>  master : in, node; slaves : in, nodes; comps : in, (6, n_slaves) their components
    !>  weights : in, (n_slaves) COEF_ESCL
    !>  b : out, (6, n_terms) with n_terms = count(comps): the slaves' components in order
    !>  st : out, S^T W S singular (the slaves do not fix a rigid motion)
    subroutine rbe3_coefficients(mesh, master, slaves, comps, weights, b, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: master, slaves(:)
        logical, intent(in) :: comps(:, :)
        real(dp), intent(in) :: weights(:)
        real(dp), allocatable, intent(out) :: b(:, :)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: s(:, :), w(:)
        real(dp) :: r(3), lc, a(6, 6), x(6, 6)
        integer(i4) :: n, i, k, row
        n = count(comps)
        allocate (s(n, 6), w(n), source=0.0_dp)
        lc = 0.0_dp
        do i = 1, size(slaves)
            lc = lc + norm2(mesh%coords(:, slaves(i)) - mesh%coords(:, master))
        end do
        lc = lc / real(size(slaves), dp)
        row = 0
        do i = 1, size(slaves)
            r = mesh%coords(:, slaves(i)) - mesh%coords(:, master)
            do k = 1, 6
                if (.not. comps(k, i)) cycle
                row = row + 1
                s(row, k) = 1.0_dp
                select case (k)
                case (1)
                    s(row, 5:6) = [r(3), -r(2)]
                case (2)
                    s(row, 4) = -r(3)
                    s(row, 6) = r(1)
                case (3)
                    s(row, 4:5) = [r(2), -r(1)]
                end select
                w(row) = weights(i)
                if (k > 3) w(row) = weights(i) * lc**2
            end do
        end do
        a = matmul(transpose(s), spread(w, 2, 6) * s)
        call invert_spd6(a, x, st)
        if (st%failed()) then
            call set_error(st, STATUS_MODEL_ERROR, 'the slaves'' components do not fix a ' // &
                'rigid motion of the master (S^T W S is singular): give more slave nodes ' // &
                'or components (DDL_ESCL)')
            return
        end if
        b = matmul(x, transpose(spread(w, 2, 6) * s))
    end subroutine rbe3_coefficients

    ! Inverse of a 6 x 6 symmetric matrix by Gauss-Jordan with partial pivoting; a pivot
    ! below 1e-12 of the largest diagonal term is a singular matrix. The zero blocks of a
    ! plane set of slaves stay exact zeros (no fill across them).
    subroutine invert_spd6(a, x, st)
        real(dp), intent(in) :: a(6, 6)
        real(dp), intent(out) :: x(6, 6)
        type(status_t), intent(out) :: st
        real(dp) :: m(6, 12), f, big
        integer :: i, j, p
        m = 0.0_dp
        m(:, 1:6) = a
        do i = 1, 6
            m(i, 6 + i) = 1.0_dp
        end do
        big = maxval([(abs(a(i, i)), i = 1, 6)])
        do i = 1, 6
            p = maxloc(abs(m(i:6, i)), dim=1) + i - 1
            if (.not. abs(m(p, i)) > 1.0e-12_dp * big) then
                call set_error(st, STATUS_MODEL_ERROR, 'singular')
                return
            end if
            if (p /= i) m([i, p], :) = m([p, i], :)
            m(i, :) = m(i, :) / m(i, i)
            do j = 1, 6
                if (j == i) cycle
                f = m(j, i)
                if (.not. abs(f) > 0.0_dp) cycle
                m(j, :) = m(j, :) - f * m(i, :)
            end do
        end do
        x = m(:, 7:12)
    end subroutine invert_spd6

    !> LIAISON_GROUP (Code_Aster U4.44.01): each node of group 1 with the node of group 2
    !> nearest to its image x' = CENTRE + P (x - CENTRE) + TRAN (P of ANGL_NAUT); the
    !> pairing must be one to one.
    !>  nodes1, nodes2 : in, the groups' nodes (same count)
    !>  tran, centre : in, (3); frame : in, (3, 3) rows as nautical_frame (identity: none)
    !>  partner : out, (size(nodes1)) the node of group 2 of each node of group 1
    !>  st : out, counts that differ, a node of group 2 taken twice
    subroutine pair_nodes(mesh, nodes1, nodes2, tran, frame, centre, partner, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: nodes1(:), nodes2(:)
        real(dp), intent(in) :: tran(3), frame(3, 3), centre(3)
        integer(i4), intent(out) :: partner(size(nodes1))
        type(status_t), intent(out) :: st
        integer(i4) :: i, j, best, used_by
        integer(i4), allocatable :: owner(:)
        real(dp) :: x(3), d, dbest
        partner = 0
        if (size(nodes1) /= size(nodes2)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the two groups have ' // &
                to_text(size(nodes1, kind=i4)) // ' and ' // to_text(size(nodes2, kind=i4)) &
                // ' nodes: LIAISON_GROUP pairs them one to one')
            return
        end if
        allocate (owner(size(nodes2)), source=0_i4)
        do i = 1, size(nodes1)
            ! rows of frame are the rotated axes: the image of a vector v is frame^T v
            x = centre + matmul(transpose(frame), mesh%coords(:, nodes1(i)) - centre) + tran
            best = 0
            dbest = huge(1.0_dp)
            do j = 1, size(nodes2)
                d = norm2(mesh%coords(:, nodes2(j)) - x)
                if (d < dbest) then
                    dbest = d
                    best = j
                end if
            end do
            used_by = owner(best)
            if (used_by > 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'nodes ' // node_name(mesh, &
                    nodes1(used_by)) // ' and ' // node_name(mesh, nodes1(i)) // ' of the ' // &
                    'first group both face node ' // node_name(mesh, nodes2(best)) // &
                    ' of the second (at ' // real_e13(dbest) // '): the pairing is not ' // &
                    'one to one')
                return
            end if
            owner(best) = i
            partner(i) = nodes2(best)
        end do
    end subroutine pair_nodes

end module model_relations
