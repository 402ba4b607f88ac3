!> Linear relations between equations, eliminated (doc/analysis.md, "Linear relations").
!>
!> The relations of the loads of an analysis (LIAISON_*, FACE_IMPO DNOR, ...: model_loads
!> RELATION items) are rows sum_k a_k u_k = beta over the original equations. Each row
!> makes one equation a SLAVE, expressed in the others:
!>     u_s = sum_j c_sj u_j + sum_r d_sr beta_r,
!> the u_j being free (master) or imposed (DDL_IMPO, AFFE_CHAR_CINE) equations, never
!> slaves. The analysis then solves for the free equations only: with T the map from the
!> free equations to all (identity on the free ones, c on the slaves) the matrix is T^T K T
!> and the right-hand side T^T (f_ext - f_int); displacements are u = T u_free + g, g the
!> imposed values and the beta part. T^T K T stays symmetric positive definite when the
!> structure is held, so every solver (LDLT, MULT_FRONT, MUMPS, the contact Newton's
!> conjugate gradients) takes it as it is, and its pivots are those of the structure's
!> own free motions: NPREC judges the structure, not multipliers.
!>
!> The slaves are chosen row by row (Gaussian elimination of the rows): each row, the
!> slaves of the earlier rows substituted, takes as slave the free equation of its own that
!> appears in the fewest rows among those whose coefficient is at least PIVOT_RATIO of the
!> row's largest (Markowitz's choice with threshold pivoting: the solid's own node rather
!> than its master, no coefficient ratio beyond 1/PIVOT_RATIO); a row whose free terms are
!> all below DEPENDENT_RATIO of its original coefficients repeats or contradicts the rows
!> before it (and the imposed values): Code_Aster's dualised system would be singular there,
!> and the row is an error naming it. Rows of one load equal to a later row of the same load
!> (the same terms up to a factor) are dropped, the later one kept, as Code_Aster's ordlrl
!> does.
module assembly_relations
    use kinds, only: dp, i4
    use status, only: status_t, set_error, add_context, STATUS_MODEL_ERROR
    use strings, only: to_text
    implicit none
    private

    !> A row's slave coefficient must be at least this fraction of its largest free one.
    real(dp), parameter :: PIVOT_RATIO = 0.1_dp
    !> A row whose free coefficients are all below this fraction of its own largest
    !> coefficient (after the earlier slaves are substituted) depends on the rows before it.
    real(dp), parameter :: DEPENDENT_RATIO = 1.0e-10_dp
    !> Two rows whose normalised coefficients differ by at most this are the same relation
    !> (Code_Aster ordlrl: 1e4 machine epsilons).
    real(dp), parameter :: SAME_ROW_TOLERANCE = 1.0e4_dp * epsilon(1.0_dp)

    !> The rows of an analysis, with where each comes from (for its right-hand side and
    !> for messages): load number (EXCIT occurrence), item, relation in the item.
    type, public :: relation_rows_t
        integer(i4) :: n = 0
        integer(i4), allocatable :: ptr(:)            !< (n + 1)
        integer(i4), allocatable :: eq(:)             !< original equations
        real(dp), allocatable :: coef(:)
        integer(i4), allocatable :: load(:), item(:), rel(:)   !< (n)
        logical, allocatable :: dropped(:)            !< (n) repeated later in its load
    end type relation_rows_t

    !> The elimination: slaves and their expressions (see the module header).
    type, public :: elimination_t
        integer(i4) :: n_slaves = 0
        integer(i4), allocatable :: slave_of(:)       !< (n_equations) index of the slave, 0
        integer(i4), allocatable :: slave_eq(:)       !< (n_slaves) its equation
        integer(i4), allocatable :: ptr(:)            !< (n_slaves + 1) terms over equations
        integer(i4), allocatable :: term_eq(:)        !<   free or imposed equations
        real(dp), allocatable :: term_coef(:)
        integer(i4), allocatable :: rhs_ptr(:)        !< (n_slaves + 1) terms over rows
        integer(i4), allocatable :: rhs_row(:)
        real(dp), allocatable :: rhs_coef(:)
        logical, allocatable :: in_relation(:)        !< (n_equations) in a kept row
        type(relation_rows_t) :: rows
    end type elimination_t

    !> A growing expression: terms over equations and over rows.
    type :: expression_t
        integer(i4) :: n = 0, m = 0
        integer(i4), allocatable :: eq(:), row(:)
        real(dp), allocatable :: c(:), d(:)
    end type expression_t

    public :: rows_append, eliminate_relations, apply_relations, expand_free, &
        reduce_to_free, has_relations, touches_slave, element_transform, reduce_element

contains

    !> Appends one row (terms over original equations, coefficients) from relation `rel`
    !> of item `item` of load `load`.
    subroutine rows_append(rows, eqs, coefs, load, item, rel)
        type(relation_rows_t), intent(inout) :: rows
        integer(i4), intent(in) :: eqs(:), load, item, rel
        real(dp), intent(in) :: coefs(:)
        integer(i4) :: m
        if (.not. allocated(rows%ptr)) then
            allocate (rows%ptr(17), rows%load(16), rows%item(16), rows%rel(16))
            allocate (rows%eq(64), rows%coef(64))
            rows%ptr(1) = 1
        end if
        if (rows%n + 1 > size(rows%load)) then
            call grow_i(rows%ptr, 2 * size(rows%load) + 1)
            call grow_i(rows%load, 2 * size(rows%load))
            call grow_i(rows%item, 2 * size(rows%item))
            call grow_i(rows%rel, 2 * size(rows%rel))
        end if
        m = rows%ptr(rows%n + 1) - 1
        if (m + size(eqs) > size(rows%eq)) then
            call grow_i(rows%eq, 2 * (m + size(eqs)))
            call grow_r(rows%coef, 2 * (m + size(eqs)))
        end if
        rows%eq(m + 1:m + size(eqs)) = eqs
        rows%coef(m + 1:m + size(eqs)) = coefs
        rows%n = rows%n + 1
        rows%ptr(rows%n + 1) = m + size(eqs, kind=i4) + 1
        rows%load(rows%n) = load
        rows%item(rows%n) = item
        rows%rel(rows%n) = rel
    end subroutine rows_append

    !> True when the elimination has slaves.
    pure logical function has_relations(elim)
        type(elimination_t), intent(in) :: elim
        has_relations = elim%n_slaves > 0
    end function has_relations

    !> Eliminates the rows (see the module header).
    !>  rows     : in, the relations (moved into elim%rows)
    !>  imposed  : in, (n_equations) equations with an imposed value
    !>  elim     : out, slaves and expressions
    !>  bad_row  : out, the row that depends on the ones before it (0 when none)
    !>  st       : out, STATUS_MODEL_ERROR for a dependent row (the caller names it with
    !>             bad_row), or a row on an equation that does not exist
    subroutine eliminate_relations(rows, imposed, elim, bad_row, st)
        type(relation_rows_t), intent(inout) :: rows
        logical, intent(in) :: imposed(:)
        type(elimination_t), intent(out) :: elim
        integer(i4), intent(out) :: bad_row
        type(status_t), intent(out) :: st
        type(expression_t), allocatable :: expr(:), users(:)
        type(expression_t) :: row
        integer(i4), allocatable :: count_of(:), local_of(:)
        integer(i4) :: n_eq, r, p, k, s, n_local
        real(dp) :: scale
        n_eq = size(imposed, kind=i4)
        bad_row = 0
        allocate (elim%slave_of(n_eq), source=0_i4)
        allocate (elim%in_relation(n_eq), source=.false.)
        allocate (count_of(n_eq), local_of(n_eq), source=0_i4)
        call move_rows(rows, elim%rows)
        call mark_repeated_rows(elim%rows)
        n_local = 0
        associate (rw => elim%rows)
            do r = 1, rw%n
                if (rw%dropped(r)) cycle
                do k = rw%ptr(r), rw%ptr(r + 1) - 1
                    if (rw%eq(k) < 1 .or. rw%eq(k) > n_eq) then
                        call set_error(st, STATUS_MODEL_ERROR, 'a relation on a component ' &
                            // 'no element carries')
                        bad_row = r
                        return
                    end if
                    count_of(rw%eq(k)) = count_of(rw%eq(k)) + 1
                    elim%in_relation(rw%eq(k)) = .true.
                    if (local_of(rw%eq(k)) == 0) then
                        n_local = n_local + 1
                        local_of(rw%eq(k)) = n_local
                    end if
                end do
            end do
            ! expressions use only equations of the rows: users(local_of(eq)) lists the
            ! expressions that use eq
            allocate (expr(rw%n), users(n_local))
            do r = 1, rw%n
                if (rw%dropped(r)) cycle
                call substituted_row(rw, r, elim%slave_of, expr, row, scale)
                p = pivot_of(row, imposed, elim%slave_of, count_of, scale)
                if (p == 0) then
                    bad_row = r
                    call set_error(st, STATUS_MODEL_ERROR, 'repeats or ' // &
                        'contradicts the relations and imposed values before it')
                    return
                end if
                s = elim%n_slaves + 1
                elim%n_slaves = s
                call solve_for(row, p, expr(s))
                call substitute_in_users(local_of(p), s, p, expr, users, local_of)
                elim%slave_of(p) = s
                do k = 1, expr(s)%n
                    call push(users(local_of(expr(s)%eq(k))), s)
                end do
            end do
        end associate
        call compress(expr, elim)
    end subroutine eliminate_relations

    ! Row r with every slave replaced by its expression: terms over non-slave equations
    ! (row%eq, row%c) and right-hand-side terms (row%row, row%d: u = sum d beta moved
    ! to the right, so the row reads sum c u = sum d beta). scale: the row's largest
    ! original coefficient.
    subroutine substituted_row(rw, r, slave_of, expr, row, scale)
        type(relation_rows_t), intent(in) :: rw
        integer(i4), intent(in) :: r, slave_of(:)
        type(expression_t), intent(in) :: expr(:)
        type(expression_t), intent(out) :: row
        real(dp), intent(out) :: scale
        integer(i4) :: k, s, j
        real(dp) :: a
        allocate (row%eq(8), row%c(8), row%row(4), row%d(4))
        call add_row_term(row, r, 1.0_dp)
        scale = 0.0_dp
        do k = rw%ptr(r), rw%ptr(r + 1) - 1
            a = rw%coef(k)
            scale = max(scale, abs(a))
            s = slave_of(rw%eq(k))
            if (s == 0) then
                call add_eq_term(row, rw%eq(k), a)
            else
                do j = 1, expr(s)%n
                    call add_eq_term(row, expr(s)%eq(j), a * expr(s)%c(j))
                end do
                do j = 1, expr(s)%m
                    call add_row_term(row, expr(s)%row(j), -a * expr(s)%d(j))
                end do
            end if
        end do
    end subroutine substituted_row

    ! The slave of a substituted row: among its free equations whose coefficient is at
    ! least PIVOT_RATIO of the largest, the one in the fewest rows (then the largest
    ! coefficient, then the smallest equation); 0 when every free coefficient is below
    ! DEPENDENT_RATIO of the row's scale (the row depends on the earlier ones).
    integer(i4) function pivot_of(row, imposed, slave_of, count_of, scale) result(p)
        type(expression_t), intent(in) :: row
        logical, intent(in) :: imposed(:)
        integer(i4), intent(in) :: slave_of(:), count_of(:)
        real(dp), intent(in) :: scale
        real(dp) :: biggest, a
        integer(i4) :: k, eq
        p = 0
        biggest = 0.0_dp
        do k = 1, row%n
            eq = row%eq(k)
            if (imposed(eq) .or. slave_of(eq) > 0) cycle
            biggest = max(biggest, abs(row%c(k)))
        end do
        if (.not. biggest > DEPENDENT_RATIO * scale) return
        do k = 1, row%n
            eq = row%eq(k)
            if (imposed(eq) .or. slave_of(eq) > 0) cycle
            a = abs(row%c(k))
            if (a < PIVOT_RATIO * biggest) cycle
            if (p == 0) then
                p = eq
            else if (count_of(eq) < count_of(p)) then
                p = eq
            else if (count_of(eq) == count_of(p)) then
                if (a > abs(coef_of(row, p)) .or. (.not. a < abs(coef_of(row, p)) .and. &
                    eq < p)) p = eq
            end if
        end do
    end function pivot_of

    pure real(dp) function coef_of(row, eq)
        type(expression_t), intent(in) :: row
        integer(i4), intent(in) :: eq
        integer(i4) :: k
        coef_of = 0.0_dp
        do k = 1, row%n
            if (row%eq(k) == eq) coef_of = coef_of + row%c(k)
        end do
    end function coef_of

    ! u_p from the row sum c u = sum d beta: u_p = (sum d beta - sum_{j /= p} c_j u_j) / c_p.
    subroutine solve_for(row, p, e)
        type(expression_t), intent(in) :: row
        integer(i4), intent(in) :: p
        type(expression_t), intent(out) :: e
        real(dp) :: cp
        integer(i4) :: k
        cp = coef_of(row, p)
        allocate (e%eq(max(row%n, 1_i4)), e%c(max(row%n, 1_i4)), e%row(max(row%m, 1_i4)), &
            e%d(max(row%m, 1_i4)))
        do k = 1, row%n
            if (row%eq(k) == p .or. .not. abs(row%c(k)) > 0.0_dp) cycle
            call add_eq_term(e, row%eq(k), -row%c(k) / cp)
        end do
        do k = 1, row%m
            call add_row_term(e, row%row(k), row%d(k) / cp)
        end do
    end subroutine solve_for

    ! The new slave p (expression s; lp its local index) replaces p in every earlier
    ! expression that uses it.
    subroutine substitute_in_users(lp, s, p, expr, users, local_of)
        integer(i4), intent(in) :: lp, s, p, local_of(:)
        type(expression_t), intent(inout) :: expr(:)
        type(expression_t), intent(inout) :: users(:)
        integer(i4) :: i, u, k, j
        real(dp) :: c
        do i = 1, users(lp)%n
            u = users(lp)%eq(i)
            if (u == s) cycle
            c = 0.0_dp
            do k = 1, expr(u)%n
                if (expr(u)%eq(k) /= p) cycle
                c = c + expr(u)%c(k)
                expr(u)%c(k) = 0.0_dp
            end do
            if (.not. abs(c) > 0.0_dp) cycle
            do j = 1, expr(s)%n
                call add_eq_term(expr(u), expr(s)%eq(j), c * expr(s)%c(j))
                call push(users(local_of(expr(s)%eq(j))), u)
            end do
            do j = 1, expr(s)%m
                call add_row_term(expr(u), expr(s)%row(j), c * expr(s)%d(j))
            end do
        end do
        users(lp)%n = 0
    end subroutine substitute_in_users

    ! The expressions into elim's CSR arrays (terms with a zero coefficient left out).
    subroutine compress(expr, elim)
        type(expression_t), intent(in) :: expr(:)
        type(elimination_t), intent(inout) :: elim
        integer(i4) :: s, k, nt, nr, eq
        allocate (elim%slave_eq(elim%n_slaves), elim%ptr(elim%n_slaves + 1), &
            elim%rhs_ptr(elim%n_slaves + 1))
        do eq = 1, size(elim%slave_of, kind=i4)
            if (elim%slave_of(eq) > 0) elim%slave_eq(elim%slave_of(eq)) = eq
        end do
        nt = 0
        nr = 0
        do s = 1, elim%n_slaves
            nt = nt + count(abs(expr(s)%c(1:expr(s)%n)) > 0.0_dp)
            nr = nr + count(abs(expr(s)%d(1:expr(s)%m)) > 0.0_dp)
        end do
        allocate (elim%term_eq(nt), elim%term_coef(nt), elim%rhs_row(nr), elim%rhs_coef(nr))
        elim%ptr(1) = 1
        elim%rhs_ptr(1) = 1
        nt = 0
        nr = 0
        do s = 1, elim%n_slaves
            do k = 1, expr(s)%n
                if (.not. abs(expr(s)%c(k)) > 0.0_dp) cycle
                nt = nt + 1
                elim%term_eq(nt) = expr(s)%eq(k)
                elim%term_coef(nt) = expr(s)%c(k)
            end do
            do k = 1, expr(s)%m
                if (.not. abs(expr(s)%d(k)) > 0.0_dp) cycle
                nr = nr + 1
                elim%rhs_row(nr) = expr(s)%row(k)
                elim%rhs_coef(nr) = expr(s)%d(k)
            end do
            elim%ptr(s + 1) = nt + 1
            elim%rhs_ptr(s + 1) = nr + 1
        end do
    end subroutine compress

    !> Sets the slave equations of u from the others and the rows' right-hand sides:
    !> u_s = sum c u_j + sum d beta_r.
    !>  beta : in, (rows%n) the right-hand side of each row at the instant
    pure subroutine apply_relations(elim, beta, u)
        type(elimination_t), intent(in) :: elim
        real(dp), intent(in) :: beta(:)
        real(dp), intent(inout) :: u(:)
        integer(i4) :: s, k
        real(dp) :: v
        do s = 1, elim%n_slaves
            v = 0.0_dp
            do k = elim%ptr(s), elim%ptr(s + 1) - 1
                v = v + elim%term_coef(k) * u(elim%term_eq(k))
            end do
            do k = elim%rhs_ptr(s), elim%rhs_ptr(s + 1) - 1
                v = v + elim%rhs_coef(k) * beta(elim%rhs_row(k))
            end do
            u(elim%slave_eq(s)) = v
        end do
    end subroutine apply_relations

    !> v = T x: the free values x (free numbering) on all equations, the slaves from them
    !> (the homogeneous part: imposed equations and right-hand sides 0).
    !>  free_eq : in, (n_equations) free number of each equation, 0 if none
    !>  free_to_eq : in, (n_free)
    pure subroutine expand_free(elim, free_eq, free_to_eq, x, v)
        type(elimination_t), intent(in) :: elim
        integer(i4), intent(in) :: free_eq(:), free_to_eq(:)
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: v(:)
        integer(i4) :: s, k, f
        real(dp) :: w
        v = 0.0_dp
        v(free_to_eq) = x
        do s = 1, elim%n_slaves
            w = 0.0_dp
            do k = elim%ptr(s), elim%ptr(s + 1) - 1
                f = free_eq(elim%term_eq(k))
                if (f > 0) w = w + elim%term_coef(k) * x(f)
            end do
            v(elim%slave_eq(s)) = w
        end do
    end subroutine expand_free

    !> x = T^T v: a vector on all equations reduced to the free ones (each slave's value
    !> spread over its free terms).
    pure subroutine reduce_to_free(elim, free_eq, free_to_eq, v, x)
        type(elimination_t), intent(in) :: elim
        integer(i4), intent(in) :: free_eq(:), free_to_eq(:)
        real(dp), intent(in) :: v(:)
        real(dp), intent(out) :: x(:)
        integer(i4) :: s, k, f
        x = v(free_to_eq)
        do s = 1, elim%n_slaves
            do k = elim%ptr(s), elim%ptr(s + 1) - 1
                f = free_eq(elim%term_eq(k))
                if (f > 0) x(f) = x(f) + elim%term_coef(k) * v(elim%slave_eq(s))
            end do
        end do
    end subroutine reduce_to_free

    !> True when one of the equations eqs (0: absent) is a slave.
    pure logical function touches_slave(elim, eqs)
        type(elimination_t), intent(in) :: elim
        integer(i4), intent(in) :: eqs(:)
        integer(i4) :: k
        touches_slave = .false.
        if (elim%n_slaves == 0) return
        do k = 1, size(eqs)
            if (eqs(k) <= 0) cycle
            if (elim%slave_of(eqs(k)) > 0) then
                touches_slave = .true.
                return
            end if
        end do
    end function touches_slave

    !> The free equations an element's equations depend on and the element's part of T:
    !> u(eqs(i)) = sum_j te(i, j) x(red(j)) + (imposed and right-hand-side parts).
    !>  eqs  : in, the element's original equations (0: absent)
    !>  red  : out, red(1:m) the free numbers, each once
    !>  te   : out, te(1:size(eqs), 1:m)
    subroutine element_transform(elim, free_eq, eqs, red, te, m)
        type(elimination_t), intent(in) :: elim
        integer(i4), intent(in) :: free_eq(:), eqs(:)
        integer(i4), allocatable, intent(out) :: red(:)
        real(dp), allocatable, intent(out) :: te(:, :)
        integer(i4), intent(out) :: m
        integer(i4) :: i, k, s, f, j, n
        integer(i4), allocatable :: list(:)
        n = size(eqs, kind=i4)
        allocate (list(4 * n + 8))
        m = 0
        do i = 1, n
            if (eqs(i) <= 0) cycle
            s = elim%slave_of(eqs(i))
            if (s == 0) then
                call add_free(free_eq(eqs(i)))
            else
                do k = elim%ptr(s), elim%ptr(s + 1) - 1
                    call add_free(free_eq(elim%term_eq(k)))
                end do
            end if
        end do
        red = list(1:m)
        allocate (te(n, m), source=0.0_dp)
        do i = 1, n
            if (eqs(i) <= 0) cycle
            s = elim%slave_of(eqs(i))
            if (s == 0) then
                f = free_eq(eqs(i))
                if (f > 0) te(i, findloc(red, f, dim=1)) = 1.0_dp
            else
                do k = elim%ptr(s), elim%ptr(s + 1) - 1
                    f = free_eq(elim%term_eq(k))
                    if (f <= 0) cycle
                    j = findloc(red, f, dim=1)
                    te(i, j) = te(i, j) + elim%term_coef(k)
                end do
            end if
        end do
    contains
        subroutine add_free(free)
            integer(i4), intent(in) :: free
            integer(i4), allocatable :: bigger(:)
            if (free <= 0) return
            if (any(list(1:m) == free)) return
            if (m == size(list)) then
                allocate (bigger(2 * size(list)))
                bigger(1:m) = list(1:m)
                call move_alloc(bigger, list)
            end if
            m = m + 1
            list(m) = free
        end subroutine add_free
    end subroutine element_transform

    !> The element matrix on the free equations it depends on: te^T ke te (element_transform).
    !>  kred : out, (m, m)
    subroutine reduce_element(te, ke, kred)
        real(dp), intent(in) :: te(:, :), ke(:, :)
        real(dp), intent(out) :: kred(:, :)
        real(dp), allocatable :: kt(:, :)
        kt = matmul(ke, te)
        kred = matmul(transpose(te), kt)
    end subroutine reduce_element

    ! Rows of one load equal, up to a factor, to a later row of the same load are dropped
    ! (Code_Aster ordlrl keeps the last of equal relations). The rows are sorted by (load,
    ! first equation, term count): equal rows are neighbours in a group, compared pairwise.
    subroutine mark_repeated_rows(rw)
        type(relation_rows_t), intent(inout) :: rw
        integer(i4), allocatable :: order(:)
        integer(i4) :: a, b, i, j, r, q
        allocate (rw%dropped(rw%n), source=.false.)
        allocate (order(rw%n))
        order = [(r, r = 1, rw%n)]
        call sort_rows(rw, order)
        a = 1
        do while (a <= rw%n)
            b = a
            do while (b < rw%n)
                if (row_key_compare(rw, order(a), order(b + 1)) /= 0) exit
                b = b + 1
            end do
            do i = a, b
                r = order(i)
                do j = a, b
                    q = order(j)
                    if (q <= r) cycle
                    if (same_row(rw, r, q)) then
                        rw%dropped(r) = .true.
                        exit
                    end if
                end do
            end do
            a = b + 1
        end do
    end subroutine mark_repeated_rows

    ! -1, 0, 1 as row r's key (load, first equation, term count) is below, equal to or
    ! above row q's.
    pure integer function row_key_compare(rw, r, q) result(c)
        type(relation_rows_t), intent(in) :: rw
        integer(i4), intent(in) :: r, q
        integer(i4) :: kr(3), kq(3), k
        kr = [rw%load(r), rw%eq(rw%ptr(r)), rw%ptr(r + 1) - rw%ptr(r)]
        kq = [rw%load(q), rw%eq(rw%ptr(q)), rw%ptr(q + 1) - rw%ptr(q)]
        c = 0
        do k = 1, 3
            if (kr(k) < kq(k)) then
                c = -1
                return
            else if (kr(k) > kq(k)) then
                c = 1
                return
            end if
        end do
    end function row_key_compare

    ! Merge sort of the row indices by row_key_compare, ties by row index (stable).
    subroutine sort_rows(rw, order)
        type(relation_rows_t), intent(in) :: rw
        integer(i4), intent(inout) :: order(:)
        integer(i4), allocatable :: work(:)
        integer(i4) :: width, lo, mid, hi, i, j, k, n
        n = size(order, kind=i4)
        allocate (work(n))
        width = 1
        do while (width < n)
            lo = 1
            do while (lo <= n)
                mid = min(lo + width - 1, n)
                hi = min(lo + 2 * width - 1, n)
                i = lo
                j = mid + 1
                k = lo
                do while (i <= mid .and. j <= hi)
                    if (row_key_compare(rw, order(j), order(i)) < 0) then
                        work(k) = order(j)
                        j = j + 1
                    else
                        work(k) = order(i)
                        i = i + 1
                    end if
                    k = k + 1
                end do
                do while (i <= mid)
                    work(k) = order(i)
                    i = i + 1
                    k = k + 1
                end do
                do while (j <= hi)
                    work(k) = order(j)
                    j = j + 1
                    k = k + 1
                end do
                lo = hi + 1
            end do
            order = work
            width = 2 * width
        end do
    end subroutine sort_rows

    ! Rows r and q have the same equations with proportional coefficients. Each row is
    ! scaled by its largest coefficient first (entries in [-1, 1]), so that no ratio of two
    ! coefficients is formed: a coefficient of 1e-308 beside one of 1 (a normal nearly along
    ! an axis) overflowed the ratio.
    pure logical function same_row(rw, r, q)
        type(relation_rows_t), intent(in) :: rw
        integer(i4), intent(in) :: r, q
        integer(i4) :: n, k, ir, iq
        real(dp) :: scale_r, scale_q, flip, u_r, u_q
        same_row = .false.
        n = rw%ptr(r + 1) - rw%ptr(r)
        if (rw%ptr(q + 1) - rw%ptr(q) /= n .or. n == 0) return
        ir = rw%ptr(r)
        iq = rw%ptr(q)
        scale_r = maxval(abs(rw%coef(ir:ir + n - 1)))
        scale_q = maxval(abs(rw%coef(iq:iq + n - 1)))
        if (.not. (scale_r > 0.0_dp .and. scale_q > 0.0_dp)) return
        if (.not. abs(rw%coef(ir)) > 0.0_dp) return
        flip = sign(1.0_dp, rw%coef(iq)) * sign(1.0_dp, rw%coef(ir))
        do k = 0, n - 1
            if (rw%eq(iq + k) /= rw%eq(ir + k)) return
            u_r = flip * (rw%coef(ir + k) / scale_r)
            u_q = rw%coef(iq + k) / scale_q
            if (abs(u_q - u_r) > SAME_ROW_TOLERANCE * max(abs(u_q), abs(u_r))) return
        end do
        same_row = .true.
    end function same_row

    subroutine move_rows(from, to)
        type(relation_rows_t), intent(inout) :: from
        type(relation_rows_t), intent(out) :: to
        to%n = from%n
        if (.not. allocated(from%ptr)) then
            allocate (to%ptr(1), to%eq(0), to%coef(0), to%load(0), to%item(0), to%rel(0))
            to%ptr(1) = 1
            return
        end if
        call move_alloc(from%ptr, to%ptr)
        call move_alloc(from%eq, to%eq)
        call move_alloc(from%coef, to%coef)
        call move_alloc(from%load, to%load)
        call move_alloc(from%item, to%item)
        call move_alloc(from%rel, to%rel)
        from%n = 0
    end subroutine move_rows

    ! Adds c to the term of equation eq (a new term when absent).
    subroutine add_eq_term(e, eq, c)
        type(expression_t), intent(inout) :: e
        integer(i4), intent(in) :: eq
        real(dp), intent(in) :: c
        integer(i4) :: k
        do k = 1, e%n
            if (e%eq(k) == eq) then
                e%c(k) = e%c(k) + c
                return
            end if
        end do
        if (.not. allocated(e%eq)) allocate (e%eq(4), e%c(4))
        if (e%n == size(e%eq)) then
            call grow_i(e%eq, 2 * size(e%eq))
            call grow_r(e%c, 2 * size(e%c))
        end if
        e%n = e%n + 1
        e%eq(e%n) = eq
        e%c(e%n) = c
    end subroutine add_eq_term

    ! Adds d to the term of row r of the right-hand side.
    subroutine add_row_term(e, r, d)
        type(expression_t), intent(inout) :: e
        integer(i4), intent(in) :: r
        real(dp), intent(in) :: d
        integer(i4) :: k
        do k = 1, e%m
            if (e%row(k) == r) then
                e%d(k) = e%d(k) + d
                return
            end if
        end do
        if (.not. allocated(e%row)) allocate (e%row(4), e%d(4))
        if (e%m == size(e%row)) then
            call grow_i(e%row, 2 * size(e%row))
            call grow_r(e%d, 2 * size(e%d))
        end if
        e%m = e%m + 1
        e%row(e%m) = r
        e%d(e%m) = d
    end subroutine add_row_term

    ! Appends s to a list of expressions (kept in the eq component) once.
    subroutine push(list, s)
        type(expression_t), intent(inout) :: list
        integer(i4), intent(in) :: s
        if (list%n > 0) then
            if (list%eq(list%n) == s) return
        end if
        if (.not. allocated(list%eq)) allocate (list%eq(2), list%c(0))
        if (list%n == size(list%eq)) call grow_i(list%eq, 2 * size(list%eq))
        list%n = list%n + 1
        list%eq(list%n) = s
    end subroutine push

    subroutine grow_i(a, n)
        integer(i4), allocatable, intent(inout) :: a(:)
        integer, intent(in) :: n
        integer(i4), allocatable :: b(:)
        allocate (b(n), source=0_i4)
        b(1:size(a)) = a
        call move_alloc(b, a)
    end subroutine grow_i

    subroutine grow_r(a, n)
        real(dp), allocatable, intent(inout) :: a(:)
        integer, intent(in) :: n
        real(dp), allocatable :: b(:)
        allocate (b(n), source=0.0_dp)
        b(1:size(a)) = a
        call move_alloc(b, a)
    end subroutine grow_r

end module assembly_relations
