!> Symmetric matrices in skyline (profile) storage: profile from element connectivity,
!> assembly of element matrices by equation numbers, matrix-vector product, profile figures.
!>
!> Storage (upper triangle by columns, as in FEAP and Code_Aster's LDLT): column j holds the
!> rows top(j)..j contiguously, the diagonal last. `diag(j)` is the position of a(j,j) in
!> `values`, with diag(0) = 0, so column j occupies values(diag(j-1)+1 : diag(j)) and
!>     top(j) = j - (diag(j) - diag(j-1)) + 1,   a(i,j) = values(diag(j) - (j - i)).
!> The column height of j is j - top(j) (entries above the diagonal); the bandwidth is the
!> largest column height (the KD of LAPACK's band storage); the profile size is the number of
!> stored entries, n + sum of heights. Pointers are integer(i8) (style.md: a profile passes
!> 2**31 entries near a million equations).
!>
!> Building a profile: `skyline_start_profile`, then `skyline_add_connectivity` for every
!> element, then `skyline_finish_profile`; or `skyline_build_profile` for elements given in
!> CSR form. Equation number 0 marks an eliminated DOF and is skipped everywhere.
module skyline_matrix
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    implicit none
    private

    !> A symmetric matrix in skyline storage (see the module header for the layout).
    type, public :: skyline_t
        integer(i4) :: n = 0                      !< number of equations
        integer(i8), allocatable :: diag(:)       !< diag(0:n), position of a(j,j) in values
        real(dp), allocatable :: values(:)        !< the stored upper profile, by columns
        logical :: profile_ready = .false.        !< diag and values allocated and final
        logical :: factored = .false.             !< values hold L D L^T (skyline_solver)
    end type skyline_t

    public :: skyline_start_profile, skyline_add_connectivity, skyline_finish_profile
    public :: skyline_build_profile, skyline_zero, skyline_add_element, skyline_matvec
    public :: skyline_profile_size, skyline_bandwidth, skyline_mean_height
    public :: skyline_column_top, skyline_entry, skyline_diagonal

contains

    !> Starts building the profile of an n-equation matrix (every column holds only its
    !> diagonal until connectivity is added).
    !>  sky : out, the matrix being built
    !>  n   : in, number of equations (>= 0)
    !>  st  : out, STATUS_INTERNAL if n < 0
    subroutine skyline_start_profile(sky, n, st)
        type(skyline_t), intent(out) :: sky
        integer(i4), intent(in) :: n
        type(status_t), intent(out) :: st
        if (n < 0) then
            call set_error(st, STATUS_INTERNAL, 'skyline: negative number of equations ' // &
                           to_text(n))
            return
        end if
        sky%n = n
        ! While building, diag(j) holds the length of column j (height + 1).
        allocate (sky%diag(0:n))
        sky%diag = 1_i8
        sky%diag(0) = 0_i8
    end subroutine skyline_start_profile

    !> Adds the coupling of one element to the profile being built: every column reaches up
    !> to the smallest equation of the element (Bathe, Finite Element Procedures, 12.2.3).
    !>  sky : inout, matrix started by skyline_start_profile
    !>  eqs : in, equation numbers of the element DOFs (0 = eliminated, skipped)
    !>  st  : out, STATUS_INTERNAL if an equation is outside 0..n or the profile is final
    subroutine skyline_add_connectivity(sky, eqs, st)
        type(skyline_t), intent(inout) :: sky
        integer(i4), intent(in) :: eqs(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, j, low
        if (sky%profile_ready .or. .not. allocated(sky%diag)) then
            call set_error(st, STATUS_INTERNAL, 'skyline: connectivity added outside ' // &
                           'skyline_start_profile/skyline_finish_profile')
            return
        end if
        if (any(eqs < 0 .or. eqs > sky%n)) then
            call set_error(st, STATUS_INTERNAL, 'skyline: element equation outside 0..' // &
                           to_text(sky%n))
            return
        end if
        low = huge(low)
        do k = 1, size(eqs)
            if (eqs(k) > 0) low = min(low, eqs(k))
        end do
        do k = 1, size(eqs)
            j = eqs(k)
            if (j > 0) sky%diag(j) = max(sky%diag(j), int(j - low + 1, i8))
        end do
    end subroutine skyline_add_connectivity

    !> Turns the column lengths into diagonal pointers and allocates the values (zeroed).
    !>  sky : inout, matrix whose connectivity is complete
    !>  st  : out, STATUS_INTERNAL if the profile was not started or is already final
    subroutine skyline_finish_profile(sky, st)
        type(skyline_t), intent(inout) :: sky
        type(status_t), intent(out) :: st
        integer(i4) :: j
        if (sky%profile_ready .or. .not. allocated(sky%diag)) then
            call set_error(st, STATUS_INTERNAL, 'skyline: profile finished twice or not ' // &
                           'started')
            return
        end if
        do j = 1, sky%n
            sky%diag(j) = sky%diag(j - 1) + sky%diag(j)
        end do
        allocate (sky%values(sky%diag(sky%n)))
        sky%values = 0.0_dp
        sky%profile_ready = .true.
        sky%factored = .false.
    end subroutine skyline_finish_profile

    !> Builds the profile from elements given in CSR form: element e has the equations
    !> elem_eqs(elem_ptr(e) : elem_ptr(e+1)-1) (0 = eliminated DOF).
    !>  sky      : out, the matrix with final profile and zero values
    !>  n        : in, number of equations
    !>  elem_ptr : in, size (number of elements + 1), elem_ptr(1) = 1
    !>  elem_eqs : in, equation numbers of all elements
    !>  st       : out, STATUS_INTERNAL on inconsistent input
    subroutine skyline_build_profile(sky, n, elem_ptr, elem_eqs, st)
        type(skyline_t), intent(out) :: sky
        integer(i4), intent(in) :: n
        integer(i4), intent(in) :: elem_ptr(:), elem_eqs(:)
        type(status_t), intent(out) :: st
        integer(i4) :: e
        call skyline_start_profile(sky, n, st)
        if (st%failed()) return
        do e = 1, size(elem_ptr) - 1
            if (elem_ptr(e) < 1 .or. elem_ptr(e + 1) - 1 > size(elem_eqs) .or. &
                elem_ptr(e + 1) < elem_ptr(e)) then
                call set_error(st, STATUS_INTERNAL, 'skyline: bad element pointer for ' // &
                               'element ' // to_text(e))
                return
            end if
            call skyline_add_connectivity(sky, elem_eqs(elem_ptr(e):elem_ptr(e + 1) - 1), st)
            if (st%failed()) return
        end do
        call skyline_finish_profile(sky, st)
    end subroutine skyline_build_profile

    !> Sets every stored value to zero (before a new assembly) and marks it unfactored.
    subroutine skyline_zero(sky)
        type(skyline_t), intent(inout) :: sky
        if (allocated(sky%values)) sky%values = 0.0_dp
        sky%factored = .false.
    end subroutine skyline_zero

    !> Adds a symmetric element matrix: A(eqs(a), eqs(b)) += ke(a, b) for the stored upper
    !> triangle. Rows/columns with equation 0 (eliminated DOFs) are skipped; an equation that
    !> appears twice gets both contributions.
    !>  sky : inout, matrix with a final profile built from the same connectivity
    !>  eqs : in, equation numbers of the element DOFs, size m
    !>  ke  : in, the element matrix, m x m, symmetric (only pairs with row <= column used)
    !>  st  : out, STATUS_INTERNAL if sizes differ, an equation is out of range or an entry
    !>        falls outside the profile (connectivity missing from the profile)
    subroutine skyline_add_element(sky, eqs, ke, st)
        type(skyline_t), intent(inout) :: sky
        integer(i4), intent(in) :: eqs(:)
        real(dp), intent(in) :: ke(:, :)
        type(status_t), intent(out) :: st
        integer(i4) :: a, b, i, j, m
        integer(i8) :: pos
        m = size(eqs)
        if (size(ke, 1) /= m .or. size(ke, 2) /= m .or. .not. sky%profile_ready) then
            call set_error(st, STATUS_INTERNAL, 'skyline: element matrix size differs from ' &
                           // 'its equation list, or profile not built')
            return
        end if
        if (any(eqs < 0 .or. eqs > sky%n)) then
            call set_error(st, STATUS_INTERNAL, 'skyline: element equation outside 0..' // &
                           to_text(sky%n))
            return
        end if
        do b = 1, m
            j = eqs(b)
            if (j == 0) cycle
            do a = 1, m
                i = eqs(a)
                if (i == 0 .or. i > j) cycle
                if (j - i > sky%diag(j) - sky%diag(j - 1) - 1) then
                    call set_error(st, STATUS_INTERNAL, 'skyline: entry (' // to_text(i) // &
                                   ',' // to_text(j) // ') outside the profile')
                    return
                end if
                pos = sky%diag(j) - (j - i)
                sky%values(pos) = sky%values(pos) + ke(a, b)
            end do
        end do
        sky%factored = .false.
    end subroutine skyline_add_element

    !> y = A x with the stored (unfactored) symmetric matrix, e.g. for residuals.
    !>  sky : in, matrix (not factored: the product would be meaningless)
    !>  x   : in, size n
    !>  y   : out, size n
    pure subroutine skyline_matvec(sky, x, y)
        type(skyline_t), intent(in) :: sky
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: y(:)
        call matvec_kernel(sky%n, sky%diag, sky%values, x, y)
    end subroutine skyline_matvec

    !> Kernel of skyline_matvec on plain arrays: column j contributes its upper part to rows
    !> top..j-1 (axpy) and its transpose to row j (dot product).
    pure subroutine matvec_kernel(n, diag, values, x, y)
        integer(i4), intent(in) :: n
        integer(i8), intent(in) :: diag(0:n)
        real(dp), intent(in) :: values(:), x(n)
        real(dp), intent(out) :: y(n)
        integer(i4) :: j, top, i
        integer(i8) :: p0
        y = 0.0_dp
        do j = 1, n
            top = j - int(diag(j) - diag(j - 1), i4) + 1
            p0 = diag(j - 1) + 1 - top       ! values(p0 + i) = a(i, j)
            do i = top, j - 1
                y(i) = y(i) + values(p0 + i) * x(j)
                y(j) = y(j) + values(p0 + i) * x(i)
            end do
            y(j) = y(j) + values(diag(j)) * x(j)
        end do
    end subroutine matvec_kernel

    !> Number of stored entries (n + sum of column heights).
    pure integer(i8) function skyline_profile_size(sky)
        type(skyline_t), intent(in) :: sky
        skyline_profile_size = 0_i8
        if (allocated(sky%diag)) skyline_profile_size = sky%diag(sky%n)
    end function skyline_profile_size

    !> Largest column height max_j (j - top(j)): the half bandwidth KD of LAPACK band storage.
    pure integer(i4) function skyline_bandwidth(sky)
        type(skyline_t), intent(in) :: sky
        integer(i4) :: j
        skyline_bandwidth = 0
        do j = 1, sky%n
            skyline_bandwidth = max(skyline_bandwidth, int(sky%diag(j) - sky%diag(j - 1), i4) - 1)
        end do
    end function skyline_bandwidth

    !> Mean column height (profile size - n) / n, 0 for an empty matrix.
    pure real(dp) function skyline_mean_height(sky)
        type(skyline_t), intent(in) :: sky
        skyline_mean_height = 0.0_dp
        if (sky%n > 0) skyline_mean_height = real(sky%diag(sky%n) - sky%n, dp) / real(sky%n, dp)
    end function skyline_mean_height

    !> First stored row of column j.
    pure integer(i4) function skyline_column_top(sky, j)
        type(skyline_t), intent(in) :: sky
        integer(i4), intent(in) :: j
        skyline_column_top = j - int(sky%diag(j) - sky%diag(j - 1), i4) + 1
    end function skyline_column_top

    !> Entry a(i, j) of the symmetric matrix (0 outside the profile).
    pure real(dp) function skyline_entry(sky, i, j)
        type(skyline_t), intent(in) :: sky
        integer(i4), intent(in) :: i, j
        integer(i4) :: r, c
        r = min(i, j)
        c = max(i, j)
        skyline_entry = 0.0_dp
        if (r >= skyline_column_top(sky, c)) skyline_entry = sky%values(sky%diag(c) - (c - r))
    end function skyline_entry

    !> Copy of the diagonal a(j, j), j = 1..n (e.g. the originals NPREC compares pivots to).
    pure function skyline_diagonal(sky) result(d)
        type(skyline_t), intent(in) :: sky
        real(dp) :: d(sky%n)
        d = sky%values(sky%diag(1:sky%n))
    end function skyline_diagonal

end module skyline_matrix
