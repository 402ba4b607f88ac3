!> The assembled symmetric matrix every solver back-end reads: compressed sparse columns
!> of the upper triangle (row <= column), rows sorted within each column, the diagonal
!> always stored. The pattern is built once per DOF numbering from the element
!> connectivity; the values are then zeroed and filled in place at each reassembly, so an
!> analysis keeps one matrix whatever the number of factorizations.
!>
!> Layout: column j holds rows row_index(col_ptr(j) : col_ptr(j+1)-1), increasing, its last
!> entry being the diagonal; values(k) is a(row_index(k), j). col_ptr is integer(i8)
!> (style.md: the stored terms pass 2**31 near a million equations with fill).
!>
!> Envelope figures (profile = n + sum over columns of j - top(j), top(j) = first coupled
!> row; bandwidth = max (j - top(j))) are what a skyline solver would store; they are
!> computed here from the element connectivity so the renumbering can be judged without
!> building a skyline.
module sparse_matrix
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    use huge_pages, only: advise_huge_pages
    implicit none
    private

    !> Upper triangle of a symmetric matrix, compressed by columns (module header).
    type, public :: sym_matrix_t
        integer(i4) :: n = 0                        !< number of equations
        integer(i8), allocatable :: col_ptr(:)      !< (n + 1), col_ptr(1) = 1
        integer(i4), allocatable :: row_index(:)    !< (nnz) rows, sorted per column
        real(dp), allocatable :: values(:)          !< (nnz)
    end type sym_matrix_t

    public :: sym_pattern_from_elements, sym_zero, sym_add_element, sym_matvec, &
        sym_nonzeros, sym_diagonal, sym_entry, envelope_of_elements, sym_from_dense, sym_move

contains

    !> Builds the pattern of the matrix coupling the equations of each element (element e
    !> has equations elem_eqs(elem_ptr(e) : elem_ptr(e+1)-1), 0 = eliminated), with every
    !> diagonal stored; values are zero.
    !>  a        : out, the matrix
    !>  n        : in, number of equations (>= 0)
    !>  elem_ptr : in, (n_elements + 1), elem_ptr(1) = 1
    !>  elem_eqs : in, equations of all elements
    !>  st       : out, STATUS_INTERNAL for an equation outside 0..n or a bad pointer
    subroutine sym_pattern_from_elements(a, n, elem_ptr, elem_eqs, st)
        type(sym_matrix_t), intent(out) :: a
        integer(i4), intent(in) :: n, elem_ptr(:), elem_eqs(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: eq_ptr(:), eq_elems(:), marker(:), rows(:)
        integer(i4) :: e, k, j, i, m, n_elem, p
        integer(i8) :: nnz
        n_elem = size(elem_ptr) - 1
        if (n < 0 .or. n_elem < 0) then
            call set_error(st, STATUS_INTERNAL, 'sparse pattern: negative size')
            return
        end if
        do e = 1, n_elem
            if (elem_ptr(e) < 1 .or. elem_ptr(e + 1) < elem_ptr(e) .or. &
                elem_ptr(e + 1) - 1 > size(elem_eqs)) then
                call set_error(st, STATUS_INTERNAL, 'sparse pattern: bad pointer of ' // &
                    'element ' // to_text(e))
                return
            end if
        end do
        if (any(elem_eqs(1:max(0, elem_ptr(n_elem + 1) - 1)) < 0) .or. &
            any(elem_eqs(1:max(0, elem_ptr(n_elem + 1) - 1)) > n)) then
            call set_error(st, STATUS_INTERNAL, 'sparse pattern: element equation ' // &
                'outside 0..' // to_text(n))
            return
        end if
        ! equation -> elements (CSR)
        allocate (eq_ptr(n + 2), source=0_i4)
        do e = 1, n_elem
            do k = elem_ptr(e), elem_ptr(e + 1) - 1
                if (elem_eqs(k) > 0) eq_ptr(elem_eqs(k) + 2) = eq_ptr(elem_eqs(k) + 2) + 1
            end do
        end do
        eq_ptr(1) = 1
        eq_ptr(2) = 1
        do j = 1, n
            eq_ptr(j + 2) = eq_ptr(j + 2) + eq_ptr(j + 1)
        end do
        allocate (eq_elems(max(1, eq_ptr(n + 2) - 1)))
        do e = 1, n_elem
            do k = elem_ptr(e), elem_ptr(e + 1) - 1
                j = elem_eqs(k)
                if (j <= 0) cycle
                eq_elems(eq_ptr(j + 1)) = e
                eq_ptr(j + 1) = eq_ptr(j + 1) + 1
            end do
        end do
        ! column j: the rows i <= j of the elements holding j (two passes: count, fill)
        allocate (marker(n), source=0_i4)
        allocate (a%col_ptr(n + 1), rows(max(1, n)))
        a%n = n
        a%col_ptr(1) = 1
        do p = 1, 2
            marker = 0
            nnz = 0
            do j = 1, n
                m = 0
                call add_row(j)
                do k = eq_ptr(j), eq_ptr(j + 1) - 1
                    e = eq_elems(k)
                    do i = elem_ptr(e), elem_ptr(e + 1) - 1
                        if (elem_eqs(i) > 0 .and. elem_eqs(i) <= j) call add_row(elem_eqs(i))
                    end do
                end do
                if (p == 1) then
                    a%col_ptr(j + 1) = a%col_ptr(j) + m
                else
                    call sort_rows(rows(1:m))
                    a%row_index(a%col_ptr(j):a%col_ptr(j + 1) - 1) = rows(1:m)
                end if
            end do
            if (p == 1) then
                allocate (a%row_index(a%col_ptr(n + 1) - 1), a%values(a%col_ptr(n + 1) - 1))
                call advise_huge_pages(a%row_index)
                call advise_huge_pages(a%values)
            end if
        end do
        a%values = 0.0_dp
    contains
        subroutine add_row(i_row)
            integer(i4), intent(in) :: i_row
            if (marker(i_row) == j) return
            marker(i_row) = j
            m = m + 1
            rows(m) = i_row
        end subroutine add_row
    end subroutine sym_pattern_from_elements

    !> Insertion sort (columns hold a few dozen rows).
    pure subroutine sort_rows(r)
        integer(i4), intent(inout) :: r(:)
        integer(i4) :: i, k, x
        do i = 2, size(r)
            x = r(i)
            k = i - 1
            do while (k >= 1)
                if (r(k) <= x) exit
                r(k + 1) = r(k)
                k = k - 1
            end do
            r(k + 1) = x
        end do
    end subroutine sort_rows

    !> Moves the matrix `from` into `to` (no copy; `from` is left empty).
    subroutine sym_move(from, to)
        type(sym_matrix_t), intent(inout) :: from
        type(sym_matrix_t), intent(out) :: to
        to%n = from%n
        if (allocated(from%col_ptr)) call move_alloc(from%col_ptr, to%col_ptr)
        if (allocated(from%row_index)) call move_alloc(from%row_index, to%row_index)
        if (allocated(from%values)) call move_alloc(from%values, to%values)
        from%n = 0
    end subroutine sym_move

    !> Zeroes the values before a new assembly (the pattern stays).
    subroutine sym_zero(a)
        type(sym_matrix_t), intent(inout) :: a
        if (allocated(a%values)) a%values = 0.0_dp
    end subroutine sym_zero

    !> Position of a(i, j), i <= j, in values (binary search in column j); 0 if absent.
    pure integer(i8) function position(a, i, j) result(pos)
        type(sym_matrix_t), intent(in) :: a
        integer(i4), intent(in) :: i, j
        integer(i8) :: lo, hi, mid
        lo = a%col_ptr(j)
        hi = a%col_ptr(j + 1) - 1
        pos = 0
        do while (lo <= hi)
            mid = (lo + hi) / 2
            if (a%row_index(mid) == i) then
                pos = mid
                return
            else if (a%row_index(mid) < i) then
                lo = mid + 1
            else
                hi = mid - 1
            end if
        end do
    end function position

    !> Adds a symmetric element matrix: a(eqs(p), eqs(q)) += ke(p, q) for the pairs with
    !> eqs(p) <= eqs(q) (upper triangle); equation 0 (eliminated) is skipped.
    !>  st : out, STATUS_INTERNAL if sizes differ, an equation is out of range, or an entry
    !>       is not in the pattern (the pattern was built from other elements)
    subroutine sym_add_element(a, eqs, ke, st)
        type(sym_matrix_t), intent(inout) :: a
        integer(i4), intent(in) :: eqs(:)
        real(dp), intent(in) :: ke(:, :)
        type(status_t), intent(out) :: st
        integer(i4) :: p, q, i, j, m
        integer(i8) :: pos
        m = size(eqs)
        if (size(ke, 1) /= m .or. size(ke, 2) /= m .or. .not. allocated(a%col_ptr)) then
            call set_error(st, STATUS_INTERNAL, 'sparse matrix: element matrix size ' // &
                'differs from its equation list, or no pattern')
            return
        end if
        if (any(eqs < 0 .or. eqs > a%n)) then
            call set_error(st, STATUS_INTERNAL, 'sparse matrix: element equation outside ' // &
                '0..' // to_text(a%n))
            return
        end if
        do q = 1, m
            j = eqs(q)
            if (j == 0) cycle
            do p = 1, m
                i = eqs(p)
                if (i == 0 .or. i > j) cycle
                pos = position(a, i, j)
                if (pos == 0) then
                    call set_error(st, STATUS_INTERNAL, 'sparse matrix: entry (' // &
                        to_text(i) // ',' // to_text(j) // ') outside the pattern')
                    return
                end if
                a%values(pos) = a%values(pos) + ke(p, q)
            end do
        end do
    end subroutine sym_add_element

    !> y = A x with the symmetric matrix (both triangles).
    pure subroutine sym_matvec(a, x, y)
        type(sym_matrix_t), intent(in) :: a
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: y(:)
        integer(i4) :: j, i
        integer(i8) :: k
        y = 0.0_dp
        do j = 1, a%n
            do k = a%col_ptr(j), a%col_ptr(j + 1) - 1
                i = a%row_index(k)
                y(i) = y(i) + a%values(k) * x(j)
                if (i /= j) y(j) = y(j) + a%values(k) * x(i)
            end do
        end do
    end subroutine sym_matvec

    !> Stored terms (upper triangle with the diagonal).
    pure integer(i8) function sym_nonzeros(a)
        type(sym_matrix_t), intent(in) :: a
        sym_nonzeros = 0
        if (allocated(a%col_ptr)) sym_nonzeros = a%col_ptr(a%n + 1) - 1
    end function sym_nonzeros

    !> The diagonal a(j, j), j = 1..n (0 where the pattern has none).
    pure function sym_diagonal(a) result(d)
        type(sym_matrix_t), intent(in) :: a
        real(dp) :: d(a%n)
        integer(i4) :: j
        integer(i8) :: k
        do j = 1, a%n
            d(j) = 0.0_dp
            k = a%col_ptr(j + 1) - 1
            if (k >= a%col_ptr(j)) then
                if (a%row_index(k) == j) d(j) = a%values(k)
            end if
        end do
    end function sym_diagonal

    !> Entry a(i, j) of the symmetric matrix (0 outside the pattern).
    pure real(dp) function sym_entry(a, i, j)
        type(sym_matrix_t), intent(in) :: a
        integer(i4), intent(in) :: i, j
        integer(i8) :: pos
        pos = position(a, min(i, j), max(i, j))
        sym_entry = 0.0_dp
        if (pos > 0) sym_entry = a%values(pos)
    end function sym_entry

    !> The matrix of a dense symmetric array (upper triangle, every entry stored: tests and
    !> small benchmarks).
    subroutine sym_from_dense(dense, a)
        real(dp), intent(in) :: dense(:, :)
        type(sym_matrix_t), intent(out) :: a
        integer(i4) :: j, i
        integer(i8) :: k
        a%n = size(dense, 1, kind=i4)
        allocate (a%col_ptr(a%n + 1), a%row_index(int(a%n, i8) * (a%n + 1) / 2), &
            a%values(int(a%n, i8) * (a%n + 1) / 2))
        a%col_ptr(1) = 1
        k = 0
        do j = 1, a%n
            do i = 1, j
                k = k + 1
                a%row_index(k) = i
                a%values(k) = dense(i, j)
            end do
            a%col_ptr(j + 1) = k + 1
        end do
    end subroutine sym_from_dense

    !> Envelope of the matrix of the elements: profile = n + sum_j (j - top(j)) stored
    !> terms and bandwidth = max_j (j - top(j)), top(j) = smallest equation coupled to j.
    !>  n, elem_ptr, elem_eqs : in, as sym_pattern_from_elements (already checked there)
    pure subroutine envelope_of_elements(n, elem_ptr, elem_eqs, profile, bandwidth)
        integer(i4), intent(in) :: n, elem_ptr(:), elem_eqs(:)
        integer(i8), intent(out) :: profile
        integer(i4), intent(out) :: bandwidth
        integer(i4) :: top(n), e, k, low, j
        do j = 1, n
            top(j) = j
        end do
        do e = 1, size(elem_ptr) - 1
            low = huge(low)
            do k = elem_ptr(e), elem_ptr(e + 1) - 1
                if (elem_eqs(k) > 0) low = min(low, elem_eqs(k))
            end do
            do k = elem_ptr(e), elem_ptr(e + 1) - 1
                j = elem_eqs(k)
                if (j > 0) top(j) = min(top(j), low)
            end do
        end do
        profile = n
        bandwidth = 0
        do j = 1, n
            profile = profile + (j - top(j))
            bandwidth = max(bandwidth, j - top(j))
        end do
    end subroutine envelope_of_elements

end module sparse_matrix
