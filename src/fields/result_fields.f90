!> The fields of a result concept (evol_elas, evol_noli, evol_ther, ...), stored per
!> NUME_ORDRE with its INST (doc/architecture.md, "Fields and results").
!>
!> This is the part of a result every layer may read: the stored instants and the fields
!> stored at each (by NOM_CHAM: DEPL, SIGM_ELNO, TEMP, ...). The analysis layer extends it
!> (analysis_result: the structure the result was computed on and the analysis's own raw
!> state, from which the post layer derives DEPL, SIEF_ELGA, ... when a command asks); a
!> result made by CREA_RESU holds only stored fields. Layers above the analysis (AFFE_VARC
!> reading an EVOL_THER, MODI_MAILLAGE reading a DEPL) use this base type only.
!>
!> Stored instants are numbered 1 .. n_stored in storage order ("index"); nume_ordre(index)
!> and inst(index) are what the deck names them by.
module result_fields
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, real_e13, to_upper
    use deck_concept, only: concept_t
    use field_types, only: field_t
    implicit none
    private

    !> Relative tolerance for matching a requested INST to a stored one (Code_Aster's
    !> default PRECISION for instants, CRITERE='RELATIF': 1e-6).
    real(dp), parameter, public :: RESULT_INST_PRECISION = 1.0e-6_dp

    !> A field stored under its NOM_CHAM.
    type, public :: named_field_t
        character(len=:), allocatable :: name
        type(field_t) :: field
    end type named_field_t

    !> The fields stored at one instant.
    type, public :: stored_fields_t
        integer(i4) :: n = 0
        type(named_field_t), allocatable :: items(:)
    end type stored_fields_t

    type, extends(concept_t), public :: result_fields_t
        character(len=:), allocatable :: kind          !< evol_elas, evol_noli, evol_ther ...
        integer(i4) :: n_stored = 0                    !< instants stored so far
        integer(i4), allocatable :: nume_ordre(:)      !< (capacity) NUME_ORDRE of each
        real(dp), allocatable :: inst(:)               !< (capacity) INST of each
        type(stored_fields_t), allocatable :: stored(:)  !< (capacity) fields of each
    contains
        procedure :: type_name => result_fields_type_name
        procedure :: summary => result_fields_summary
    end type result_fields_t

    public :: result_fields_init, result_add_instant, result_find, result_put_field, &
        result_field_index, result_stored_names, result_find_all, result_has_field

contains

    function result_fields_type_name(self) result(name)
        class(result_fields_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'evol_noli'
        if (allocated(self%kind)) name = self%kind
    end function result_fields_type_name

    !> One line for the .mess: kind, instants stored.
    function result_fields_summary(self) result(text)
        class(result_fields_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = self%type_name() // ' with ' // to_text(self%n_stored) // ' stored instants'
        if (self%n_stored > 0) text = text // ', INST ' // real_e13(self%inst(1)) // &
            ' to ' // real_e13(self%inst(self%n_stored))
    end function result_fields_summary

    !> Empties the stored instants and gives room for `capacity` (grown as needed).
    subroutine result_fields_init(res, kind, capacity)
        class(result_fields_t), intent(inout) :: res
        character(len=*), intent(in) :: kind
        integer(i4), intent(in) :: capacity
        res%kind = kind
        res%n_stored = 0
        if (allocated(res%nume_ordre)) deallocate (res%nume_ordre)
        if (allocated(res%inst)) deallocate (res%inst)
        if (allocated(res%stored)) deallocate (res%stored)
        allocate (res%nume_ordre(max(capacity, 1_i4)), res%inst(max(capacity, 1_i4)))
        allocate (res%stored(max(capacity, 1_i4)))
    end subroutine result_fields_init

    !> Adds an instant (NUME_ORDRE, INST) at the end; returns its index.
    subroutine result_add_instant(res, nume_ordre, inst, index)
        class(result_fields_t), intent(inout) :: res
        integer(i4), intent(in) :: nume_ordre
        real(dp), intent(in) :: inst
        integer(i4), intent(out) :: index
        integer(i4), allocatable :: numbers(:)
        real(dp), allocatable :: times(:)
        type(stored_fields_t), allocatable :: stored(:)
        integer(i4) :: k, capacity
        if (.not. allocated(res%nume_ordre)) call result_fields_init(res, res%type_name(), 4_i4)
        capacity = size(res%nume_ordre, kind=i4)
        if (res%n_stored == capacity) then
            allocate (numbers(2 * capacity), times(2 * capacity), stored(2 * capacity))
            numbers(1:capacity) = res%nume_ordre
            times(1:capacity) = res%inst
            do k = 1, res%n_stored
                call move_alloc(res%stored(k)%items, stored(k)%items)
                stored(k)%n = res%stored(k)%n
            end do
            call move_alloc(numbers, res%nume_ordre)
            call move_alloc(times, res%inst)
            call move_alloc(stored, res%stored)
        end if
        res%n_stored = res%n_stored + 1
        index = res%n_stored
        res%nume_ordre(index) = nume_ordre
        res%inst(index) = inst
        res%stored(index)%n = 0
    end subroutine result_add_instant

    !> Index (1..n_stored) of the stored instant asked for by INST (within `precision`,
    !> default RESULT_INST_PRECISION, relative or ABSOLU by `criterion`; relative is taken
    !> absolute below |INST| = 1) or by NUME_ORDRE.
    !>  st : STATUS_MODEL_ERROR naming the instant and listing what is stored
    subroutine result_find(res, index, st, inst, nume_ordre, precision, criterion)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(out) :: index
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: inst, precision
        integer(i4), intent(in), optional :: nume_ordre
        character(len=*), intent(in), optional :: criterion
        integer(i4) :: k
        real(dp) :: tol
        logical :: absolute
        character(len=:), allocatable :: stored
        index = 0
        tol = RESULT_INST_PRECISION
        if (present(precision)) tol = precision
        absolute = .false.
        if (present(criterion)) absolute = to_upper(criterion) == 'ABSOLU'
        do k = 1, res%n_stored
            if (present(inst)) then
                if (absolute) then
                    if (abs(res%inst(k) - inst) <= tol) index = k
                else
                    if (abs(res%inst(k) - inst) <= tol * max(abs(inst), 1.0_dp)) index = k
                end if
            else if (present(nume_ordre)) then
                if (res%nume_ordre(k) == nume_ordre) index = k
            end if
            if (index /= 0) return
        end do
        stored = ''
        do k = 1, res%n_stored
            if (k > 1) stored = stored // ', '
            if (k > 12 .and. k < res%n_stored) then
                stored = stored // '...'
                cycle
            end if
            if (present(inst)) then
                stored = stored // real_e13(res%inst(k))
            else
                stored = stored // to_text(res%nume_ordre(k))
            end if
        end do
        if (present(inst)) then
            call set_error(st, STATUS_MODEL_ERROR, 'INST ' // real_e13(inst) // &
                ' is not stored in the result (stored: ' // stored // ')')
        else if (present(nume_ordre)) then
            call set_error(st, STATUS_MODEL_ERROR, 'NUME_ORDRE ' // to_text(nume_ordre) // &
                ' is not stored in the result (stored: ' // stored // ')')
        else
            call set_error(st, STATUS_MODEL_ERROR, 'give INST or NUME_ORDRE')
        end if
    end subroutine result_find

    !> Every stored index (TOUT_ORDRE).
    pure function result_find_all(res) result(indices)
        class(result_fields_t), intent(in) :: res
        integer(i4), allocatable :: indices(:)
        integer(i4) :: k
        indices = [(k, k = 1, res%n_stored)]
    end function result_find_all

    !> Stores `field` under `name` at stored instant `index` (moved in; a field of that
    !> name stored there before is replaced, as Code_Aster's CALC_CHAMP with reuse does).
    subroutine result_put_field(res, index, name, field)
        class(result_fields_t), intent(inout) :: res
        integer(i4), intent(in) :: index
        character(len=*), intent(in) :: name
        type(field_t), intent(inout) :: field
        type(named_field_t), allocatable :: bigger(:)
        integer(i4) :: k
        associate (s => res%stored(index))
            k = result_field_index(res, index, name)
            if (k == 0) then
                if (.not. allocated(s%items)) allocate (s%items(4))
                if (s%n == size(s%items)) then
                    allocate (bigger(2 * s%n))
                    do k = 1, s%n
                        call move_alloc(s%items(k)%name, bigger(k)%name)
                        call move_field(s%items(k)%field, bigger(k)%field)
                    end do
                    call move_alloc(bigger, s%items)
                end if
                s%n = s%n + 1
                k = s%n
                s%items(k)%name = to_upper(trim(name))
            end if
            call move_field(field, s%items(k)%field)
        end associate
    end subroutine result_put_field

    !> Moves a field (its arrays change owner, no copy).
    subroutine move_field(from, to)
        type(field_t), intent(inout) :: from
        type(field_t), intent(out) :: to
        to%location = from%location
        to%n_nodes = from%n_nodes
        to%n_cells = from%n_cells
        if (allocated(from%quantity)) call move_alloc(from%quantity, to%quantity)
        if (allocated(from%components)) call move_alloc(from%components, to%components)
        if (allocated(from%node_values)) call move_alloc(from%node_values, to%node_values)
        if (allocated(from%node_has)) call move_alloc(from%node_has, to%node_has)
        if (allocated(from%n_points)) call move_alloc(from%n_points, to%n_points)
        if (allocated(from%n_subpoints)) call move_alloc(from%n_subpoints, to%n_subpoints)
        if (allocated(from%cell_set)) call move_alloc(from%cell_set, to%cell_set)
        if (allocated(from%sets)) call move_alloc(from%sets, to%sets)
        if (allocated(from%offset)) call move_alloc(from%offset, to%offset)
        if (allocated(from%values)) call move_alloc(from%values, to%values)
        if (allocated(from%family)) call move_alloc(from%family, to%family)
        if (allocated(from%functions)) call move_alloc(from%functions, to%functions)
    end subroutine move_field

    !> Position of the field `name` among those stored at `index`, 0 if none.
    pure integer(i4) function result_field_index(res, index, name) result(k)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: index
        character(len=*), intent(in) :: name
        k = 0
        if (index < 1 .or. index > res%n_stored) return
        if (.not. allocated(res%stored(index)%items)) return
        do k = 1, res%stored(index)%n
            if (res%stored(index)%items(k)%name == to_upper(trim(name))) return
        end do
        k = 0
    end function result_field_index

    !> True when field `name` is stored at `index`.
    pure logical function result_has_field(res, index, name)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: index
        character(len=*), intent(in) :: name
        result_has_field = result_field_index(res, index, name) > 0
    end function result_has_field

    !> The names of the fields stored at `index`, in storage order.
    function result_stored_names(res, index) result(names)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: index
        type(string_t), allocatable :: names(:)
        integer(i4) :: k
        if (index < 1 .or. index > res%n_stored) then
            allocate (names(0))
            return
        end if
        allocate (names(res%stored(index)%n))
        do k = 1, res%stored(index)%n
            names(k)%s = res%stored(index)%items(k)%name
        end do
    end function result_stored_names

end module result_fields
