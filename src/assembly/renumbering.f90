!> Renumbering of a graph (nodes or equations) to reduce the profile of the skyline matrix,
!> methods named as Code_Aster's SOLVEUR/RENUM:
!>   'RCMK'  reverse Cuthill-McKee, started from a pseudo-peripheral node found by repeated
!>           level structures (George & Liu 1979, "An implementation of a pseudoperipheral
!>           node finder", ACM TOMS 5(3)); each connected component is ordered in turn;
!>   'METIS' nested dissection, METIS_NodeND (Karypis & Kumar), through metis_interface;
!>   'SANS'  no renumbering (identity).
!> Graphs are in CSR form, 1-based: the neighbours of vertex i are
!> adjncy(xadj(i) : xadj(i+1)-1); the graph must be symmetric; self loops are ignored.
!> An ordering is given both ways: new_to_old(k) = vertex numbered k, old_to_new(i) = new
!> number of vertex i.
module renumbering
    use, intrinsic :: iso_c_binding, only: c_null_ptr
    use kinds, only: i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_INTERNAL
    use strings, only: to_text, to_upper
    use metis_interface, only: metis_idx, METIS_NOPTIONS, METIS_OK, METIS_OPTION_NUMBERING, &
        metis_setdefaultoptions, metis_nodend
    implicit none
    private

    public :: renumber_graph, renumber_rcm, renumber_metis, graph_profile
    public :: graph_from_elements, check_graph

contains

    !> Orders the vertices of a graph with a Code_Aster SOLVEUR/RENUM method.
    !>  method     : in, 'RCMK', 'METIS' or 'SANS' (case-insensitive)
    !>  n          : in, number of vertices
    !>  xadj       : in, size n+1, CSR pointers (1-based)
    !>  adjncy     : in, CSR neighbours
    !>  new_to_old : out, size n, vertex given new number k
    !>  old_to_new : out, size n, new number of vertex i
    !>  st         : out, STATUS_MODEL_ERROR for an unknown method, STATUS_INTERNAL for a
    !>               malformed graph or a METIS failure
    subroutine renumber_graph(method, n, xadj, adjncy, new_to_old, old_to_new, st)
        character(len=*), intent(in) :: method
        integer(i4), intent(in) :: n, xadj(:), adjncy(:)
        integer(i4), allocatable, intent(out) :: new_to_old(:), old_to_new(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k
        call check_graph(n, xadj, adjncy, st)
        if (st%failed()) return
        allocate (new_to_old(n), old_to_new(n))
        select case (to_upper(trim(adjustl(method))))
        case ('RCMK')
            call renumber_rcm(n, xadj, adjncy, new_to_old)
        case ('METIS')
            call renumber_metis(n, xadj, adjncy, new_to_old, st)
            if (st%failed()) return
        case ('SANS')
            new_to_old = [(k, k = 1, n)]
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'unknown renumbering method "' // &
                           trim(method) // '" (expected RCMK, METIS or SANS)', &
                           keyword='RENUM')
            return
        end select
        do k = 1, n
            old_to_new(new_to_old(k)) = k
        end do
    end subroutine renumber_graph

    !> Checks a CSR graph: size(xadj) = n+1, xadj(1) = 1, non-decreasing pointers within
    !> adjncy, neighbours in 1..n.
    !>  st : out, STATUS_INTERNAL naming what is malformed
    subroutine check_graph(n, xadj, adjncy, st)
        integer(i4), intent(in) :: n, xadj(:), adjncy(:)
        type(status_t), intent(out) :: st
        integer(i4) :: i
        if (n < 0 .or. size(xadj) /= n + 1) then
            call set_error(st, STATUS_INTERNAL, 'graph: xadj must have n+1 = ' // &
                           to_text(n + 1) // ' entries, has ' // to_text(size(xadj, kind=i4)))
            return
        end if
        if (xadj(1) /= 1 .or. xadj(n + 1) - 1 > size(adjncy)) then
            call set_error(st, STATUS_INTERNAL, 'graph: xadj must start at 1 and end within ' &
                           // 'adjncy')
            return
        end if
        do i = 1, n
            if (xadj(i + 1) < xadj(i)) then
                call set_error(st, STATUS_INTERNAL, 'graph: xadj decreases at vertex ' // &
                               to_text(i))
                return
            end if
        end do
        if (any(adjncy(1:xadj(n + 1) - 1) < 1 .or. adjncy(1:xadj(n + 1) - 1) > n)) then
            call set_error(st, STATUS_INTERNAL, 'graph: neighbour outside 1..' // to_text(n))
        end if
    end subroutine check_graph

    !> Reverse Cuthill-McKee ordering (Cuthill & McKee 1969; reversal: George 1971). Every
    !> connected component is started from a pseudo-peripheral vertex (George & Liu 1979)
    !> searched from its lowest-numbered vertex; neighbours are visited by increasing degree.
    !>  n, xadj, adjncy : in, a valid symmetric graph (check_graph)
    !>  new_to_old      : out, size n, the ordering
    subroutine renumber_rcm(n, xadj, adjncy, new_to_old)
        integer(i4), intent(in) :: n, xadj(:), adjncy(:)
        integer(i4), intent(out) :: new_to_old(:)
        integer(i4), allocatable :: degree(:), mark(:), level_ptr(:), order(:)
        logical, allocatable :: numbered(:)
        integer(i4) :: count, seed, root, stamp
        allocate (degree(n), mark(n), level_ptr(n + 1), order(n), numbered(n))
        call vertex_degrees(n, xadj, adjncy, degree)
        numbered = .false.
        mark = 0
        stamp = 0
        count = 0
        seed = 1
        do while (count < n)
            do while (numbered(seed))
                seed = seed + 1
            end do
            call find_pseudo_peripheral(seed, xadj, adjncy, degree, numbered, mark, stamp, &
                                        order, level_ptr, root)
            call cuthill_mckee_component(root, xadj, adjncy, degree, numbered, new_to_old, &
                                         count)
        end do
        ! The reversal (George 1971): same bandwidth, never a larger profile.
        new_to_old(1:n) = new_to_old(n:1:-1)
    end subroutine renumber_rcm

    !> Degree of every vertex, self loops not counted.
    !>  n, xadj, adjncy : in, a valid graph;  degree : out, size n
    pure subroutine vertex_degrees(n, xadj, adjncy, degree)
        integer(i4), intent(in) :: n, xadj(:), adjncy(:)
        integer(i4), intent(out) :: degree(:)
        integer(i4) :: v, k
        do v = 1, n
            degree(v) = 0
            do k = xadj(v), xadj(v + 1) - 1
                if (adjncy(k) /= v) degree(v) = degree(v) + 1
            end do
        end do
    end subroutine vertex_degrees

    !> Rooted level structure (breadth-first levels) of the component of `from` among the
    !> vertices not yet numbered: order(1:m) by levels, level l being
    !> order(level_ptr(l) : level_ptr(l+1)-1).
    !>  from            : in, the root
    !>  xadj, adjncy    : in, a valid graph;  numbered : in, vertices already ordered
    !>  mark, stamp     : inout, visit marks: a vertex is seen when mark = stamp; the stamp
    !>                    is advanced so the marks never need clearing
    !>  order, level_ptr: out, sizes n and n+1, the structure
    !>  m, n_levels     : out, vertices reached (with from) and number of levels
    pure subroutine level_structure(from, xadj, adjncy, numbered, mark, stamp, order, &
                                    level_ptr, m, n_levels)
        integer(i4), intent(in) :: from, xadj(:), adjncy(:)
        logical, intent(in) :: numbered(:)
        integer(i4), intent(inout) :: mark(:), stamp
        integer(i4), intent(inout) :: order(:), level_ptr(:)
        integer(i4), intent(out) :: m, n_levels
        integer(i4) :: head, v, k, w, level_end
        stamp = stamp + 1
        order(1) = from
        mark(from) = stamp
        m = 1
        head = 1
        n_levels = 0
        do while (head <= m)
            n_levels = n_levels + 1
            level_ptr(n_levels) = head
            level_end = m
            do while (head <= level_end)
                v = order(head)
                head = head + 1
                do k = xadj(v), xadj(v + 1) - 1
                    w = adjncy(k)
                    if (mark(w) == stamp .or. numbered(w)) cycle
                    mark(w) = stamp
                    m = m + 1
                    order(m) = w
                end do
            end do
        end do
        level_ptr(n_levels + 1) = m + 1
    end subroutine level_structure

    !> Pseudo-peripheral vertex of start's unnumbered component (George & Liu 1979): move
    !> to a minimum-degree vertex of the last level (the first one met) while the
    !> eccentricity grows.
    !>  start           : in, the vertex to search from
    !>  degree          : in, vertex degrees (vertex_degrees)
    !>  numbered, mark, stamp, order, level_ptr : as in level_structure (work arrays)
    !>  best            : out, the vertex found
    pure subroutine find_pseudo_peripheral(start, xadj, adjncy, degree, numbered, mark, stamp, &
                                           order, level_ptr, best)
        integer(i4), intent(in) :: start, xadj(:), adjncy(:), degree(:)
        logical, intent(in) :: numbered(:)
        integer(i4), intent(inout) :: mark(:), stamp, order(:), level_ptr(:)
        integer(i4), intent(out) :: best
        integer(i4) :: m, depth, new_depth, k, x
        best = start
        call level_structure(best, xadj, adjncy, numbered, mark, stamp, order, level_ptr, &
                             m, depth)
        do
            x = order(level_ptr(depth))
            do k = level_ptr(depth) + 1, level_ptr(depth + 1) - 1
                if (degree(order(k)) < degree(x)) x = order(k)
            end do
            call level_structure(x, xadj, adjncy, numbered, mark, stamp, order, level_ptr, &
                                 m, new_depth)
            if (new_depth <= depth) exit
            best = x
            depth = new_depth
        end do
    end subroutine find_pseudo_peripheral

    !> Cuthill-McKee breadth-first numbering of root's unnumbered component (Cuthill &
    !> McKee 1969): the unnumbered neighbours of each numbered vertex, in turn, get the next
    !> numbers by increasing (degree, vertex number).
    !>  root         : in, first vertex of the component (pseudo-peripheral)
    !>  degree       : in, vertex degrees;  numbered : inout, set for the vertices numbered
    !>  new_to_old   : inout, new_to_old(count+1:) receives the component
    !>  count        : inout, vertices numbered so far
    pure subroutine cuthill_mckee_component(root, xadj, adjncy, degree, numbered, new_to_old, &
                                            count)
        integer(i4), intent(in) :: root, xadj(:), adjncy(:), degree(:)
        logical, intent(inout) :: numbered(:)
        integer(i4), intent(inout) :: new_to_old(:), count
        integer(i4) :: head, v, k, w, first
        count = count + 1
        new_to_old(count) = root
        numbered(root) = .true.
        head = count
        do while (head <= count)
            v = new_to_old(head)
            head = head + 1
            first = count + 1
            do k = xadj(v), xadj(v + 1) - 1
                w = adjncy(k)
                if (numbered(w)) cycle
                numbered(w) = .true.
                count = count + 1
                new_to_old(count) = w
            end do
            call sort_by_degree(new_to_old(first:count), degree)
        end do
    end subroutine cuthill_mckee_component

    !> Insertion sort of vertices by (degree, vertex number): the lists (new neighbours of
    !> one vertex) are short.
    !>  list   : inout, vertices;  degree : in, vertex degrees
    pure subroutine sort_by_degree(list, degree)
        integer(i4), intent(inout) :: list(:)
        integer(i4), intent(in) :: degree(:)
        integer(i4) :: a, b, tmp
        do a = 2, size(list)
            tmp = list(a)
            b = a - 1
            do while (b >= 1)
                if (.not. precedes(tmp, list(b))) exit
                list(b + 1) = list(b)
                b = b - 1
            end do
            list(b + 1) = tmp
        end do
    contains
        pure logical function precedes(p, q)
            integer(i4), intent(in) :: p, q
            precedes = degree(p) < degree(q) .or. (degree(p) == degree(q) .and. p < q)
        end function precedes
    end subroutine sort_by_degree

    !> Nested-dissection ordering by METIS_NodeND (default options, C numbering). Self loops
    !> are dropped (METIS requires none); graphs without edges keep the identity.
    !>  n, xadj, adjncy : in, a valid symmetric graph (check_graph)
    !>  new_to_old      : out, size n
    !>  st              : out, STATUS_INTERNAL if METIS fails
    subroutine renumber_metis(n, xadj, adjncy, new_to_old, st)
        integer(i4), intent(in) :: n, xadj(:), adjncy(:)
        integer(i4), intent(out) :: new_to_old(:)
        type(status_t), intent(out) :: st
        integer(metis_idx), allocatable :: cxadj(:), cadj(:), perm(:), iperm(:)
        integer(metis_idx) :: options(METIS_NOPTIONS), nv
        integer(i4) :: i, k, m
        integer :: rc
        allocate (cxadj(n + 1), cadj(max(1, xadj(n + 1) - 1)), perm(n), iperm(n))
        m = 0
        cxadj(1) = 0
        do i = 1, n
            do k = xadj(i), xadj(i + 1) - 1
                if (adjncy(k) == i) cycle
                m = m + 1
                cadj(m) = int(adjncy(k) - 1, metis_idx)
            end do
            cxadj(i + 1) = int(m, metis_idx)
        end do
        if (m == 0) then
            new_to_old(1:n) = [(i, i = 1, n)]
            return
        end if
        rc = metis_setdefaultoptions(options)
        options(METIS_OPTION_NUMBERING + 1) = 0
        nv = int(n, metis_idx)
        rc = metis_nodend(nv, cxadj, cadj, c_null_ptr, options, perm, iperm)
        if (rc /= METIS_OK) then
            call set_error(st, STATUS_INTERNAL, 'METIS_NodeND failed with code ' // &
                           to_text(int(rc, i4)))
            return
        end if
        ! METIS: row k of the permuted matrix is row perm[k] of the original (0-based).
        new_to_old(1:n) = int(perm(1:n), i4) + 1
    end subroutine renumber_metis

    !> Profile size and bandwidth of the skyline a graph would give under an ordering, so
    !> callers can report them before and after renumbering. Column p (new numbering)
    !> reaches up to the smallest new number among p and its neighbours.
    !>  n, xadj, adjncy : in, a valid symmetric graph
    !>  old_to_new      : in, size n, the ordering (identity = original numbering)
    !>  profile         : out, stored entries n + sum of column heights
    !>  bandwidth       : out, largest column height
    !>  dofs_per_node   : in, optional: each vertex carries this many consecutive equations
    !>                    (vertex = node); the figures are then those of the equation matrix
    pure subroutine graph_profile(n, xadj, adjncy, old_to_new, profile, bandwidth, &
                                  dofs_per_node)
        integer(i4), intent(in) :: n, xadj(:), adjncy(:), old_to_new(:)
        integer(i8), intent(out) :: profile
        integer(i4), intent(out) :: bandwidth
        integer(i4), intent(in), optional :: dofs_per_node
        integer(i4) :: i, k, p, top, d
        integer(i8) :: h
        d = 1
        if (present(dofs_per_node)) d = dofs_per_node
        profile = 0_i8
        bandwidth = 0
        do i = 1, n
            p = old_to_new(i)
            top = p
            do k = xadj(i), xadj(i + 1) - 1
                top = min(top, old_to_new(adjncy(k)))
            end do
            ! The d equations of vertex p all reach equation (top-1)*d + 1; their heights are
            ! d*(p-top) + 0 .. d-1, summing to d*d*(p-top) + d*(d-1)/2.
            h = int(p - top, i8)
            profile = profile + int(d, i8) * (int(d, i8) * h + 1_i8) + &
                      int(d, i8) * int(d - 1, i8) / 2_i8
            bandwidth = max(bandwidth, d * (p - top) + d - 1)
        end do
    end subroutine graph_profile

    !> Vertex graph of a mesh: two nodes are neighbours when an element holds both.
    !>  n_nodes    : in, number of nodes
    !>  elem_ptr   : in, size (elements + 1): element e holds elem_nodes(elem_ptr(e) :
    !>               elem_ptr(e+1)-1)
    !>  elem_nodes : in, node numbers 1..n_nodes (0 = none, skipped)
    !>  xadj       : out, size n_nodes + 1
    !>  adjncy     : out, neighbours of each node, increasing, no self loops
    !>  st         : out, STATUS_INTERNAL if a node number is out of range
    subroutine graph_from_elements(n_nodes, elem_ptr, elem_nodes, xadj, adjncy, st)
        integer(i4), intent(in) :: n_nodes, elem_ptr(:), elem_nodes(:)
        integer(i4), allocatable, intent(out) :: xadj(:), adjncy(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: node_ptr(:), node_elems(:), mark(:), fill(:)
        integer(i4) :: n_elems, e, k, v, w, pass, m, q
        n_elems = size(elem_ptr) - 1
        if (any(elem_nodes < 0 .or. elem_nodes > n_nodes)) then
            call set_error(st, STATUS_INTERNAL, 'graph: element node outside 0..' // &
                           to_text(n_nodes))
            return
        end if
        ! Elements of each node (CSR), then the union of their nodes, twice: count, fill.
        allocate (node_ptr(n_nodes + 1), mark(n_nodes), fill(n_nodes), xadj(n_nodes + 1))
        node_ptr = 0
        do k = 1, elem_ptr(n_elems + 1) - 1
            if (elem_nodes(k) > 0) node_ptr(elem_nodes(k) + 1) = node_ptr(elem_nodes(k) + 1) + 1
        end do
        node_ptr(1) = 1
        do v = 1, n_nodes
            node_ptr(v + 1) = node_ptr(v + 1) + node_ptr(v)
        end do
        allocate (node_elems(node_ptr(n_nodes + 1) - 1))
        fill = node_ptr(1:n_nodes)
        do e = 1, n_elems
            do k = elem_ptr(e), elem_ptr(e + 1) - 1
                v = elem_nodes(k)
                if (v == 0) cycle
                node_elems(fill(v)) = e
                fill(v) = fill(v) + 1
            end do
        end do
        allocate (adjncy(0))
        do pass = 1, 2
            mark = 0
            m = 0
            xadj(1) = 1
            do v = 1, n_nodes
                mark(v) = v
                do q = node_ptr(v), node_ptr(v + 1) - 1
                    e = node_elems(q)
                    do k = elem_ptr(e), elem_ptr(e + 1) - 1
                        w = elem_nodes(k)
                        if (w == 0) cycle
                        if (mark(w) == v) cycle
                        mark(w) = v
                        m = m + 1
                        if (pass == 2) adjncy(m) = w
                    end do
                end do
                xadj(v + 1) = m + 1
                if (pass == 2) call sort_ints(adjncy(xadj(v):m))
            end do
            if (pass == 1) then
                deallocate (adjncy)
                allocate (adjncy(m))
            end if
        end do
    end subroutine graph_from_elements

    !> Insertion sort (neighbour lists are short).
    pure subroutine sort_ints(a)
        integer(i4), intent(inout) :: a(:)
        integer(i4) :: i, j, t
        do i = 2, size(a)
            t = a(i)
            j = i - 1
            do while (j >= 1)
                if (a(j) <= t) exit
                a(j + 1) = a(j)
                j = j - 1
            end do
            a(j + 1) = t
        end do
    end subroutine sort_ints

end module renumbering
