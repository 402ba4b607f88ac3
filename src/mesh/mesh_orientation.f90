!> Cell orientations of MODI_MAILLAGE (U4.23.04): the order of a cell's nodes decides its
!> normal (right-hand rule round a face; (dy, -dx) for an edge in the plane), which is what
!> pressures, shell normals and edge loads use. As Code_Aster does it:
!>  - ORIE_PEAU (orilma / utmasu / oriema): every skin cell (SEG edges of plane cells in a
!>    plane mesh; TRIA/QUAD faces of volumes) gets its normal pointing out of its support
!>    cell, the cell of the dimension above holding all its nodes (among GROUP_MA_INTERNE
!>    when given). The skin's normal is turned round when it points towards the support's
!>    centroid (from the skin's); its nodes are then listed backwards. A skin with supports
!>    on both sides is an error (GROUP_MA_INTERNE chooses); a skin with none is left as it
!>    is and counted.
!>  - ORIE_NORM_COQUE / ORIE_LIGNE without a vector (ornorm): the cells of a connected set
!>    are made consistent with its first cell: two faces sharing an edge run it in opposite
!>    senses, two lines sharing a node meet end to start. The set must be connected.
!>  - with VECT_NORM / VECT_TANG and a node (orvlma, orvlse): the cells at the node take the
!>    sense of the vector (face normal at that corner, edge normal (dy, -dx), line tangent),
!>    the rest of the set follows them; a cell no path reaches is an error.
!> A face turned round keeps its first node (nodes 2 and n swapped, mid-edge nodes
!> following: ioriv2 / iorim2); a skin turned round by ORIE_PEAU is listed backwards
!> (oriema). Each operation is O(cells + their nodes) with node-to-cell lists.
module mesh_orientation
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t, cell_name, node_name
    use mesh_cell_shapes, only: CELL_TYPE_NAMES, CELL_TYPE_CORNERS, CELL_TYPE_DIM, &
        CELL_TYPE_NODES
    use mesh_geometry, only: cross
    implicit none
    private

    !> What an orientation did, for the .mess.
    type, public :: orientation_report_t
        integer(i4) :: turned = 0          !< cells whose node order was changed
        integer(i4) :: untreated = 0       !< ORIE_PEAU: skin cells with no support cell
        integer(i4), allocatable :: turned_cells(:)   !< their numbers (INFO=2)
    end type orientation_report_t

    !> Kinds of cells an orientation works on.
    integer(i4), parameter :: LINES = 1, FACES = 2

    public :: orient_skin, orient_consistently, orient_by_vector

contains

    !> ORIE_PEAU on `cells` (SEG, or TRIA/QUAD, not both).
    !>  internal : in, cells allowed as supports (GROUP_MA_INTERNE; empty: any cell)
    !>  plane    : in, the mesh is plane (every z equal, Code_Aster's Z_CST): edges are
    !>             oriented in (x, y); in a mesh that is not plane edges are left as they are
    !>  st       : out, a cell that is not a skin type, SEG mixed with faces, supports on both
    !>             sides of a skin, a support with no thickness on the skin's side
    subroutine orient_skin(mesh, cells, internal, plane, report, st)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: cells(:), internal(:)
        logical, intent(in) :: plane
        type(orientation_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: ptr(:), incident(:), turned(:)
        logical, allocatable :: allowed(:)
        integer(i4) :: kind, support_dim, i, c, k, s, support, nturned
        real(dp) :: side, side_first
        allocate (turned(size(cells)))
        nturned = 0
        call cell_kind(mesh, cells, kind, st)
        if (st%failed()) return
        support_dim = merge(2, 3, kind == LINES)
        allocate (allowed(mesh%n_cells))
        if (size(internal) > 0) then
            allowed = .false.
            allowed(internal) = .true.
        else
            allowed = .true.
        end if
        do c = 1, mesh%n_cells
            if (CELL_TYPE_DIM(mesh%cell_type(c)) /= support_dim) allowed(c) = .false.
        end do
        call node_cells(mesh, allowed, ptr, incident)
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            if (kind == LINES .and. .not. plane) then
                report%untreated = report%untreated + 1
                cycle
            end if
            ! the supports: allowed cells at the skin's first node holding all its nodes
            support = 0
            associate (first => mesh%cell_nodes(mesh%cell_ptr(c)))
                do k = ptr(first), ptr(first + 1) - 1
                    s = incident(k)
                    if (.not. holds_all(s, c)) cycle
                    if (support == 0) then
                        support = s
                        side_first = side_of(c, s)
                        if (.not. (abs(side_first) > 0.0_dp)) then
                            call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, s) &
                                // ', support of skin cell ' // cell_name(mesh, c) // &
                                ', has no thickness on its side: which side it is on is ' // &
                                'undefined')
                            return
                        end if
                        cycle
                    end if
                    side = side_of(c, s)
                    if (.not. (abs(side) > 0.0_dp)) then
                        call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, s) // &
                            ', support of skin cell ' // cell_name(mesh, c) // ', has no ' // &
                            'thickness on its side: which side it is on is undefined')
                        return
                    end if
                    if ((side > 0.0_dp) .neqv. (side_first > 0.0_dp)) then
                        call set_error(st, STATUS_MESH_ERROR, 'skin cell ' // &
                            cell_name(mesh, c) // ' lies between cells ' // &
                            cell_name(mesh, support) // ' and ' // cell_name(mesh, s) // &
                            ', on both of its sides: say which is inside with ' // &
                            'GROUP_MA_INTERNE')
                        return
                    end if
                end do
            end associate
            if (support == 0) then
                report%untreated = report%untreated + 1
                cycle
            end if
            if (points_inwards(c, support)) then
                call reverse_all(c)
                nturned = nturned + 1
                turned(nturned) = c
            end if
        end do
        report%turned = nturned
        report%turned_cells = turned(1:nturned)
    contains
        ! Every node of cell `skin` is a node of cell `s`.
        logical function holds_all(s, skin)
            integer(i4), intent(in) :: s, skin
            integer(i4) :: p
            holds_all = .true.
            do p = mesh%cell_ptr(skin), mesh%cell_ptr(skin + 1) - 1
                if (.not. any(mesh%cell_nodes(mesh%cell_ptr(s):mesh%cell_ptr(s + 1) - 1) == &
                              mesh%cell_nodes(p))) then
                    holds_all = .false.
                    return
                end if
            end do
        end function holds_all

        ! Which side of the skin the support lies on (oriem0): the skin's normal dotted with
        ! the vector from the skin's first node to the support's first node that is not on
        ! the skin (only its sign is used, to compare two supports).
        real(dp) function side_of(skin, s) result(side)
            integer(i4), intent(in) :: skin, s
            real(dp) :: normal(3)
            integer(i4) :: p
            normal = skin_normal(skin)
            side = 0.0_dp
            do p = mesh%cell_ptr(s), mesh%cell_ptr(s + 1) - 1
                if (any(mesh%cell_nodes(mesh%cell_ptr(skin):mesh%cell_ptr(skin + 1) - 1) == &
                        mesh%cell_nodes(p))) cycle
                side = dot_product(mesh%coords(:, mesh%cell_nodes(p)) - &
                    mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(skin))), normal)
                return
            end do
        end function side_of

        ! The skin's normal by its node order: (dy, -dx, 0) for an edge, the corner cross
        ! product for a face (unnormalized).
        function skin_normal(skin) result(normal)
            integer(i4), intent(in) :: skin
            real(dp) :: normal(3), a(3), b(3)
            integer(i4) :: p
            p = mesh%cell_ptr(skin)
            a = mesh%coords(:, mesh%cell_nodes(p + 1)) - mesh%coords(:, mesh%cell_nodes(p))
            if (kind == LINES) then
                normal = [a(2), -a(1), 0.0_dp]
            else
                b = mesh%coords(:, mesh%cell_nodes(p + 2)) - mesh%coords(:, mesh%cell_nodes(p))
                normal = cross(a, b)
            end if
        end function skin_normal

        ! oriema: the skin's normal points towards the support's vertex centroid, seen from
        ! the skin's vertex centroid.
        logical function points_inwards(skin, s)
            integer(i4), intent(in) :: skin, s
            real(dp) :: to_support(3)
            to_support = vertex_centroid(s) - vertex_centroid(skin)
            points_inwards = dot_product(to_support, skin_normal(skin)) > 0.0_dp
        end function points_inwards

        function vertex_centroid(cell) result(x)
            integer(i4), intent(in) :: cell
            real(dp) :: x(3)
            integer(i4) :: p, nv
            p = mesh%cell_ptr(cell)
            nv = CELL_TYPE_CORNERS(mesh%cell_type(cell))
            x = sum(mesh%coords(:, mesh%cell_nodes(p:p + nv - 1)), dim=2) / nv
        end function vertex_centroid

        ! oriema's reversal: the vertices backwards (the last first), the mid-edge nodes
        ! following their edges, a centre node in place.
        subroutine reverse_all(cell)
            integer(i4), intent(in) :: cell
            integer(i4) :: p, nv, nn, old(9), j, mids
            p = mesh%cell_ptr(cell)
            nv = CELL_TYPE_CORNERS(mesh%cell_type(cell))
            nn = CELL_TYPE_NODES(mesh%cell_type(cell))
            old(1:nn) = mesh%cell_nodes(p:p + nn - 1)
            do j = 1, nv
                mesh%cell_nodes(p + j - 1) = old(nv + 1 - j)
            end do
            if (CELL_TYPE_DIM(mesh%cell_type(cell)) == 2 .and. nn > nv) then
                ! edge j of the reversed cell runs old vertices nv+1-j -> nv-j: its middle is
                ! old mid node nv-j (cyclic), the last edge's the old last mid node
                mids = nv
                do j = 1, mids - 1
                    mesh%cell_nodes(p + nv + j - 1) = old(nv + mids - j)
                end do
                mesh%cell_nodes(p + nv + mids - 1) = old(nv + mids)
            end if
        end subroutine reverse_all
    end subroutine orient_skin

    !> ORIE_NORM_COQUE / ORIE_LIGNE without a vector: the cells made consistent with the
    !> first of their connected set.
    !>  n_sets : out, the connected sets found (Code_Aster wants 1)
    !>  st     : out, a cell that is not a face / line type, lines mixed with faces
    subroutine orient_consistently(mesh, cells, lines_only, report, n_sets, st)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: cells(:)
        logical, intent(in) :: lines_only
        type(orientation_report_t), intent(out) :: report
        integer(i4), intent(out) :: n_sets
        type(status_t), intent(out) :: st
        integer(i4) :: kind, i
        logical, allocatable :: done(:)
        integer(i4), allocatable :: turned(:)
        integer(i4) :: nturned
        n_sets = 0
        call cell_kind(mesh, cells, kind, st, lines_only)
        if (st%ok() .and. lines_only) call check_line_branches(mesh, cells, st)
        if (st%failed()) return
        allocate (done(size(cells)), source=.false.)
        allocate (turned(size(cells)))
        nturned = 0
        do i = 1, size(cells, kind=i4)
            if (done(i)) cycle
            n_sets = n_sets + 1
            done(i) = .true.
            call propagate(mesh, cells, kind, [i], done, turned, nturned)
        end do
        report%turned = nturned
        report%turned_cells = turned(1:nturned)
    end subroutine orient_consistently

    !> ORIE_NORM_COQUE with VECT_NORM, ORIE_LIGNE with VECT_TANG: the cells at `node` take
    !> the sense of `vector`, the others follow them.
    !>  tangent : in, ORIE_LIGNE (vector along the line), else a normal
    !>  st : out, no cell at the node, a vector in the cell's plane (or across the line), a
    !>       cell no path of neighbours reaches, a cell of another kind
    subroutine orient_by_vector(mesh, cells, node, vector, tangent, report, st)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: cells(:), node
        real(dp), intent(in) :: vector(3)
        logical, intent(in) :: tangent
        type(orientation_report_t), intent(out) :: report
        type(status_t), intent(out) :: st
        integer(i4) :: kind, i, c, p, nv, j, nseed, nturned
        integer(i4), allocatable :: seeds(:), turned(:)
        logical, allocatable :: done(:)
        real(dp) :: sense, a(3), b(3)
        call cell_kind(mesh, cells, kind, st, tangent)
        if (st%ok() .and. tangent) call check_line_branches(mesh, cells, st)
        if (st%failed()) return
        allocate (done(size(cells)), source=.false.)
        allocate (seeds(size(cells)), turned(size(cells)))
        nseed = 0
        nturned = 0
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            p = mesh%cell_ptr(c)
            nv = CELL_TYPE_CORNERS(mesh%cell_type(c))
            j = findloc(mesh%cell_nodes(p:p + nv - 1), node, dim=1)
            if (j == 0) cycle
            if (kind == FACES) then
                ! the normal at corner j by the node order: (next - j) x (previous - j)
                a = mesh%coords(:, mesh%cell_nodes(p + mod(j, nv))) - mesh%coords(:, node)
                b = mesh%coords(:, mesh%cell_nodes(p + mod(j + nv - 2, nv))) - &
                    mesh%coords(:, node)
                sense = dot_product(cross(a, b), vector)
            else
                a = mesh%coords(:, mesh%cell_nodes(p + 1)) - mesh%coords(:, mesh%cell_nodes(p))
                if (tangent) then
                    sense = dot_product(a, vector)
                else
                    sense = a(2) * vector(1) - a(1) * vector(2)
                end if
            end if
            if (.not. (abs(sense) > 0.0_dp)) then
                call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, c) // ': ' // &
                    choose(tangent, 'the vector is across the line here', &
                           'the vector lies in the cell''s plane here') // &
                    ' (at node ' // node_name(mesh, node) // '): it orients nothing')
                return
            end if
            if (sense < 0.0_dp) then
                call reverse_keep_first(mesh, c)
                nturned = nturned + 1
                turned(nturned) = c
            end if
            nseed = nseed + 1
            seeds(nseed) = i
            done(i) = .true.
        end do
        if (nseed == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'no cell of the group touches node ' // &
                node_name(mesh, node) // ' (the node where the vector orients them)')
            return
        end if
        call propagate(mesh, cells, kind, seeds(1:nseed), done, turned, nturned)
        if (.not. all(done)) then
            i = findloc(done, .false., dim=1)
            call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, cells(i)) // &
                ' cannot be oriented: no path of neighbouring cells of the group leads to it ' &
                // 'from node ' // node_name(mesh, node) // ' (the group is not connected)')
            return
        end if
        report%turned = nturned
        report%turned_cells = turned(1:nturned)
    end subroutine orient_by_vector

    ! Breadth-first from the cells `start` (positions in `cells`, already oriented): each
    ! neighbour sharing an edge (faces) or a node (lines) is made consistent and queued.
    subroutine propagate(mesh, cells, kind, start, done, turned, nturned)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: cells(:), kind, start(:)
        logical, intent(inout) :: done(:)
        integer(i4), intent(inout) :: turned(:), nturned
        integer(i4), allocatable :: ptr(:), incident(:), queue(:), position(:)
        logical, allocatable :: member(:)
        integer(i4) :: head, tail, i, k, j, c, relation
        integer(i4) :: p
        allocate (member(mesh%n_cells), source=.false.)
        member(cells) = .true.
        allocate (position(mesh%n_cells), source=0_i4)
        do i = 1, size(cells, kind=i4)
            position(cells(i)) = i
        end do
        call node_cells(mesh, member, ptr, incident)
        allocate (queue(size(cells)))
        tail = size(start, kind=i4)
        queue(1:tail) = start
        head = 0
        do while (head < tail)
            head = head + 1
            c = cells(queue(head))
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c) + CELL_TYPE_CORNERS(mesh%cell_type(c)) - 1
                do k = ptr(mesh%cell_nodes(p)), ptr(mesh%cell_nodes(p) + 1) - 1
                    j = position(incident(k))
                    if (done(j)) cycle
                    if (kind == FACES) then
                        relation = face_relation(mesh, c, cells(j))
                    else
                        relation = line_relation(mesh, c, cells(j))
                    end if
                    if (relation == 0) cycle
                    if (relation < 0) then
                        call reverse_keep_first(mesh, cells(j))
                        nturned = nturned + 1
                        turned(nturned) = cells(j)
                    end if
                    done(j) = .true.
                    tail = tail + 1
                    queue(tail) = j
                end do
            end do
        end do
    end subroutine propagate

    ! iorim2: +1 when faces a and b run a shared edge in opposite senses (consistent), -1
    ! when in the same sense (b must turn), 0 when they share no edge.
    integer(i4) function face_relation(mesh, a, b) result(relation)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: a, b
        integer(i4) :: na, nb, i, j, pa, pb, ai, aj, bi, bj
        pa = mesh%cell_ptr(a)
        pb = mesh%cell_ptr(b)
        na = CELL_TYPE_CORNERS(mesh%cell_type(a))
        nb = CELL_TYPE_CORNERS(mesh%cell_type(b))
        relation = 0
        do i = 1, na
            ai = mesh%cell_nodes(pa + i - 1)
            aj = mesh%cell_nodes(pa + mod(i, na))
            do j = 1, nb
                bi = mesh%cell_nodes(pb + j - 1)
                bj = mesh%cell_nodes(pb + mod(j, nb))
                if (ai == bi .and. aj == bj) then
                    relation = -1
                    return
                end if
                if (ai == bj .and. aj == bi) then
                    relation = 1
                    return
                end if
            end do
        end do
    end function face_relation

    ! iorim1: +1 when lines a and b meet end to start, -1 when start to start or end to end
    ! (b must turn), 0 when they share no end.
    integer(i4) function line_relation(mesh, a, b) result(relation)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: a, b
        integer(i4) :: i, ea(2), eb(2)
        ea = mesh%cell_nodes(mesh%cell_ptr(a):mesh%cell_ptr(a) + 1)
        eb = mesh%cell_nodes(mesh%cell_ptr(b):mesh%cell_ptr(b) + 1)
        relation = 0
        do i = 1, 2
            if (ea(i) == eb(i)) then
                relation = -1
                return
            end if
            if (ea(i) == eb(3 - i)) then
                relation = 1
                return
            end if
        end do
    end function line_relation

    ! ioriv2 / iorim2 / iorim1's reversal: a line's ends swapped (its middle in place); a
    ! face keeps its first node, its corners 2 and n swapped and its mid-edge nodes following
    ! (i <-> n+1-i among them), a centre node in place.
    subroutine reverse_keep_first(mesh, cell)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: cell
        integer(i4) :: p, nv, nn, i, swap
        p = mesh%cell_ptr(cell)
        nv = CELL_TYPE_CORNERS(mesh%cell_type(cell))
        nn = CELL_TYPE_NODES(mesh%cell_type(cell))
        if (CELL_TYPE_DIM(mesh%cell_type(cell)) == 1) then
            swap = mesh%cell_nodes(p)
            mesh%cell_nodes(p) = mesh%cell_nodes(p + 1)
            mesh%cell_nodes(p + 1) = swap
            return
        end if
        swap = mesh%cell_nodes(p + 1)
        mesh%cell_nodes(p + 1) = mesh%cell_nodes(p + nv - 1)
        mesh%cell_nodes(p + nv - 1) = swap
        if (nn > nv) then
            do i = 1, nv / 2
                swap = mesh%cell_nodes(p + nv + i - 1)
                mesh%cell_nodes(p + nv + i - 1) = mesh%cell_nodes(p + 2 * nv - i)
                mesh%cell_nodes(p + 2 * nv - i) = swap
            end do
        end if
    end subroutine reverse_keep_first

    ! ORIE_LIGNE (orvlse, MODELISA4_84): at most two cells of a line meet at a node.
    subroutine check_line_branches(mesh, cells, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: meeting(:)
        integer(i4) :: i, p, n
        allocate (meeting(mesh%n_nodes), source=0_i4)
        do i = 1, size(cells, kind=i4)
            p = mesh%cell_ptr(cells(i))
            do n = p, p + 1
                meeting(mesh%cell_nodes(n)) = meeting(mesh%cell_nodes(n)) + 1
                if (meeting(mesh%cell_nodes(n)) > 2) then
                    call set_error(st, STATUS_MESH_ERROR, 'three cells of the line meet at ' &
                        // 'node ' // node_name(mesh, mesh%cell_nodes(n)) // ' (a line ' // &
                        'branches there: its sense is undefined)')
                    return
                end if
            end do
        end do
    end subroutine check_line_branches

    ! LINES (SEG) or FACES (TRIA, QUAD) for a set of cells; an error for other types or a
    ! mix (MODELISA5_94, MODELISA5_98). lines_only: only SEG cells are allowed (ORIE_LIGNE).
    subroutine cell_kind(mesh, cells, kind, st, lines_only)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        integer(i4), intent(out) :: kind
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: lines_only
        integer(i4) :: i, d, first_dim
        logical :: only_lines
        only_lines = .false.
        if (present(lines_only)) only_lines = lines_only
        kind = 0
        first_dim = 0
        do i = 1, size(cells, kind=i4)
            d = CELL_TYPE_DIM(mesh%cell_type(cells(i)))
            if (d < 1 .or. (only_lines .and. d /= 1)) then
                call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, cells(i)) // &
                    ' is a ' // trim(CELL_TYPE_NAMES(mesh%cell_type(cells(i)))) // ': ' // &
                    choose(only_lines, 'a line is made of SEG cells', &
                           'only SEG (lines) or TRIA, QUAD (faces) can be oriented'))
                return
            end if
            if (first_dim == 0) first_dim = d
            if (d /= first_dim) then
                call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, cells(i)) // &
                    ' is a ' // trim(CELL_TYPE_NAMES(mesh%cell_type(cells(i)))) // &
                    ' and cell ' // cell_name(mesh, cells(1)) // ' a ' // &
                    trim(CELL_TYPE_NAMES(mesh%cell_type(cells(1)))) // ': lines (SEG) ' // &
                    'and faces (TRIA, QUAD) are oriented separately')
                return
            end if
        end do
        kind = merge(LINES, FACES, first_dim == 1)
    end subroutine cell_kind

    ! Node -> cells lists (compressed rows, cells in increasing number) of the cells flagged
    ! in `member` (a cell never lists a node twice: mesh_finish refuses such cells).
    subroutine node_cells(mesh, member, ptr, incident)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: member(:)
        integer(i4), allocatable, intent(out) :: ptr(:), incident(:)
        integer(i4), allocatable :: fill(:)
        integer(i4) :: c, p, n
        allocate (ptr(mesh%n_nodes + 1), source=0_i4)
        do c = 1, mesh%n_cells
            if (.not. member(c)) cycle
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                n = mesh%cell_nodes(p)
                ptr(n + 1) = ptr(n + 1) + 1
            end do
        end do
        ptr(1) = 1
        do n = 1, mesh%n_nodes
            ptr(n + 1) = ptr(n + 1) + ptr(n)
        end do
        allocate (incident(ptr(mesh%n_nodes + 1) - 1), fill(mesh%n_nodes), source=0_i4)
        do c = 1, mesh%n_cells
            if (.not. member(c)) cycle
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                n = mesh%cell_nodes(p)
                incident(ptr(n) + fill(n)) = c
                fill(n) = fill(n) + 1
            end do
        end do
    end subroutine node_cells

    ! a when `condition`, else b.
    pure function choose(condition, a, b) result(text)
        logical, intent(in) :: condition
        character(len=*), intent(in) :: a, b
        character(len=:), allocatable :: text
        if (condition) then
            text = a
        else
            text = b
        end if
    end function choose

end module mesh_orientation
