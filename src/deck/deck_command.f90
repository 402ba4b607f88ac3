!> A validated command, as handlers receive it: every keyword checked against the catalog,
!> defaults filled in, each value normalized (a keyword of cardinality 1 holds a scalar, one
!> of higher cardinality a tuple, even when a single value was written), and the deck
!> location of the command and of every keyword kept so handlers can report located errors.
!>
!> Accessors take the keyword name and return a status located at that keyword:
!>     call cmd%get_real('EPAIS', thickness, st)            ! command level
!>     do i = 1, cmd%count('RIGI_PARASOL')                   ! factor keyword occurrences
!>         occ = cmd%occurrence('RIGI_PARASOL', i)
!>         call occ%get_reals('VALE', stiffness, st)
!>     end do
module deck_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_value
    use deck_concept, only: concept_t
    implicit none
    private

    !> A reference to a concept (for lists of concepts, e.g. MATER=(A, B)).
    type, public :: concept_ref_t
        class(concept_t), pointer :: ptr => null()
    end type concept_ref_t

    !> One keyword and its normalized value. line = 0 for a default from the catalog.
    type, public :: kw_value_t
        character(len=:), allocatable :: name
        type(value_t) :: value
        integer :: line = 0, col = 0
        logical :: is_default = .false.
    end type kw_value_t

    !> The keywords of one scope: the command level or one occurrence of a factor keyword.
    !> `scope` is the factor keyword name ('' at command level); line/col its location.
    type, public :: keyword_set_t
        character(len=:), allocatable :: file, command, scope
        integer :: line = 0, col = 0
        type(kw_value_t), allocatable :: items(:)
        integer :: n = 0
    contains
        procedure :: has => set_has
        procedure :: given => set_given
        procedure :: get_concepts => set_get_concepts
        procedure :: find => set_find
        procedure :: get_value => set_get_value
        procedure :: get_int => set_get_int
        procedure :: get_real => set_get_real
        procedure :: get_text => set_get_text
        procedure :: get_ints => set_get_ints
        procedure :: get_reals => set_get_reals
        procedure :: get_texts => set_get_texts
        procedure :: get_concept => set_get_concept
        procedure :: error_at => set_error_at
        procedure :: location => set_location
        procedure :: add => set_add
    end type keyword_set_t

    !> The occurrences of one factor keyword.
    type, public :: factor_value_t
        character(len=:), allocatable :: name
        type(keyword_set_t), allocatable :: occ(:)
        integer :: line = 0, col = 0
    end type factor_value_t

    !> A validated command. Its own keywords are the command-level scope; factor keywords
    !> are reached through count() and occurrence(). `source` is the deck text of the
    !> statement (for the .mess echo); `result_type` the catalog type of its result.
    !> `reuse`: the concept given as reuse=... (a reentrant command modifies it in place;
    !> doc/architecture.md, "reuse"), null when none.
    type, extends(keyword_set_t), public :: command_t
        character(len=:), allocatable :: name, result_type, source
        type(factor_value_t), allocatable :: factors(:)
        integer :: nfactor = 0
        class(concept_t), pointer :: reuse => null()
    contains
        procedure :: count => command_count
        procedure :: occurrence => command_occurrence
        procedure :: add_factor => command_add_factor
    end type command_t

contains

    !> Index of `key` in the scope, 0 if absent.
    pure integer function set_find(self, key)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        integer :: k
        set_find = 0
        do k = 1, self%n
            if (self%items(k)%name == key) then
                set_find = k
                return
            end if
        end do
    end function set_find

    !> True when `key` was given or has a default.
    pure logical function set_has(self, key)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        set_has = self%find(key) > 0
    end function set_has

    !> True when `key` was written in the deck (not a catalog default).
    pure logical function set_given(self, key)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        integer :: k
        k = self%find(key)
        set_given = .false.
        if (k > 0) set_given = .not. self%items(k)%is_default
    end function set_given

    !> All concepts given to `key` (one or several), aliasing objects owned by the run.
    subroutine set_get_concepts(self, key, refs, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        type(concept_ref_t), allocatable, intent(out) :: refs(:)
        type(status_t), intent(out) :: st
        type(value_t), allocatable :: items(:)
        integer :: k
        call items_of(self, key, items, st)
        allocate (refs(size(items)))
        if (st%failed()) return
        do k = 1, size(items)
            if (items(k)%kind /= VK_CONCEPT .or. .not. associated(items(k)%obj)) then
                call self%error_at(key, 'expected concepts, got ' // kind_label(items(k)), st)
                return
            end if
            refs(k)%ptr => items(k)%obj
        end do
    end subroutine set_get_concepts

    !> Appends a keyword value (used by validation).
    subroutine set_add(self, item)
        class(keyword_set_t), intent(inout) :: self
        type(kw_value_t), intent(in) :: item
        type(kw_value_t), allocatable :: bigger(:)
        if (.not. allocated(self%items)) allocate (self%items(8))
        if (self%n == size(self%items)) then
            allocate (bigger(2 * size(self%items)))
            bigger(1:self%n) = self%items(1:self%n)
            call move_alloc(bigger, self%items)
        end if
        self%n = self%n + 1
        self%items(self%n) = item
    end subroutine set_add

    !> Deck location of `key` (of the scope itself when absent or a default).
    subroutine set_location(self, key, file, line, col)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        character(len=:), allocatable, intent(out) :: file
        integer, intent(out) :: line, col
        integer :: k
        file = self%file
        line = self%line; col = self%col
        k = self%find(key)
        if (k > 0) then
            if (self%items(k)%line > 0) then
                line = self%items(k)%line; col = self%items(k)%col
            end if
        end if
    end subroutine set_location

    !> Records an error located at keyword `key` (or at the scope when absent), in the form
    !> `deck.comm:L:C: error: COMMAND/FACTOR/KEY: message`.
    !>  key : keyword name ('' = the command or occurrence itself);  message : what is wrong
    !>  st : out;  code : optional STATUS_* (default STATUS_DECK_ERROR)
    subroutine set_error_at(self, key, message, st, code)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key, message
        type(status_t), intent(inout) :: st
        integer, intent(in), optional :: code
        character(len=:), allocatable :: file, path
        integer :: line, col, c
        c = STATUS_DECK_ERROR
        if (present(code)) c = code
        call self%location(key, file, line, col)
        path = key
        if (allocated(self%scope)) then
            if (len(self%scope) > 0) then
                path = self%scope
                if (len(key) > 0) path = self%scope // '/' // key
            end if
        end if
        if (len(path) > 0) then
            call set_error(st, c, message, file=file, line=line, column=col, &
                           command=self%command, keyword=path)
        else
            call set_error(st, c, message, file=file, line=line, column=col, &
                           command=self%command)
        end if
    end subroutine set_error_at

    !> The value of `key` (VK_NONE when absent).
    function set_get_value(self, key) result(v)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        type(value_t) :: v
        integer :: k
        k = self%find(key)
        if (k > 0) v = self%items(k)%value
    end function set_get_value

    !> Scalar accessors: the value of `key`; error if absent or of another type.
    subroutine set_get_int(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        integer(i4), intent(out) :: x
        type(status_t), intent(out) :: st
        type(value_t) :: v
        x = 0
        call scalar_of(self, key, v, st)
        if (st%failed()) return
        if (v%kind /= VK_INT .and. v%kind /= VK_BOOL) then
            call self%error_at(key, 'expected an integer, got ' // kind_label(v), st); return
        end if
        if (abs(v%i) > int(huge(x), i8)) then
            call self%error_at(key, 'integer out of range', st); return
        end if
        x = int(v%i, i4)
    end subroutine set_get_int

    subroutine set_get_real(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        real(dp), intent(out) :: x
        type(status_t), intent(out) :: st
        type(value_t) :: v
        x = 0.0_dp
        call scalar_of(self, key, v, st)
        if (st%failed()) return
        if (.not. is_number(v)) then
            call self%error_at(key, 'expected a real, got ' // kind_label(v), st); return
        end if
        x = as_real(v)
    end subroutine set_get_real

    subroutine set_get_text(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        character(len=:), allocatable, intent(out) :: x
        type(status_t), intent(out) :: st
        type(value_t) :: v
        x = ''
        call scalar_of(self, key, v, st)
        if (st%failed()) return
        if (v%kind /= VK_STR) then
            call self%error_at(key, 'expected a text, got ' // kind_label(v), st); return
        end if
        x = v%s
    end subroutine set_get_text

    !> The concept given to `key`; `ptr` aliases the object owned by the run's symbol table.
    subroutine set_get_concept(self, key, ptr, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        class(concept_t), pointer, intent(out) :: ptr
        type(status_t), intent(out) :: st
        type(value_t) :: v
        ptr => null()
        call scalar_of(self, key, v, st)
        if (st%failed()) return
        if (v%kind /= VK_CONCEPT .or. .not. associated(v%obj)) then
            call self%error_at(key, 'expected a concept, got ' // kind_label(v), st); return
        end if
        ptr => v%obj
    end subroutine set_get_concept

    !> List accessors: all values of `key` (a single value gives a list of one).
    subroutine set_get_reals(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        real(dp), allocatable, intent(out) :: x(:)
        type(status_t), intent(out) :: st
        type(value_t), allocatable :: items(:)
        integer :: k
        call items_of(self, key, items, st)
        allocate (x(0))
        if (st%failed()) return
        do k = 1, size(items)
            if (.not. is_number(items(k))) then
                call self%error_at(key, 'expected reals, got ' // kind_label(items(k)), st)
                return
            end if
        end do
        x = as_real(items)
    end subroutine set_get_reals

    subroutine set_get_ints(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        integer(i4), allocatable, intent(out) :: x(:)
        type(status_t), intent(out) :: st
        type(value_t), allocatable :: items(:)
        integer :: k
        call items_of(self, key, items, st)
        allocate (x(0))
        if (st%failed()) return
        deallocate (x)
        allocate (x(size(items)))
        do k = 1, size(items)
            if (items(k)%kind /= VK_INT .or. abs(items(k)%i) > int(huge(1_i4), i8)) then
                call self%error_at(key, 'expected integers, got ' // kind_label(items(k)), st)
                return
            end if
            x(k) = int(items(k)%i, i4)
        end do
    end subroutine set_get_ints

    subroutine set_get_texts(self, key, x, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        type(string_t), allocatable, intent(out) :: x(:)
        type(status_t), intent(out) :: st
        type(value_t), allocatable :: items(:)
        integer :: k
        call items_of(self, key, items, st)
        allocate (x(0))
        if (st%failed()) return
        deallocate (x)
        allocate (x(size(items)))
        do k = 1, size(items)
            if (items(k)%kind /= VK_STR) then
                call self%error_at(key, 'expected texts, got ' // kind_label(items(k)), st)
                return
            end if
            x(k)%s = items(k)%s
        end do
    end subroutine set_get_texts

    subroutine scalar_of(self, key, v, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        integer :: k
        k = self%find(key)
        if (k == 0) then
            call self%error_at(key, 'keyword ' // key // ' is required here', st); return
        end if
        associate (given => self%items(k)%value)
            if (given%kind == VK_TUPLE .or. given%kind == VK_LIST) then
                if (nitems(given) == 1) then
                    v = item(given, 1)
                else
                    call self%error_at(key, 'expected one value, got several', st)
                end if
            else
                v = given
            end if
        end associate
    end subroutine scalar_of

    subroutine items_of(self, key, items, st)
        class(keyword_set_t), intent(in) :: self
        character(len=*), intent(in) :: key
        type(value_t), allocatable, intent(out) :: items(:)
        type(status_t), intent(inout) :: st
        type(value_list_t) :: list
        integer :: k
        k = self%find(key)
        if (k == 0) then
            allocate (items(0))
            call self%error_at(key, 'keyword ' // key // ' is required here', st); return
        end if
        associate (v => self%items(k)%value)
            if (v%kind == VK_TUPLE .or. v%kind == VK_LIST) then
                list = unpack_value(v)
                items = list%items
            else
                allocate (items(1))
                items(1) = v
            end if
        end associate
    end subroutine items_of

    !> Number of occurrences of factor keyword `name` (0 when absent).
    pure integer function command_count(self, name)
        class(command_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: k
        command_count = 0
        do k = 1, self%nfactor
            if (self%factors(k)%name == name) then
                command_count = size(self%factors(k)%occ)
                return
            end if
        end do
    end function command_count

    !> Occurrence `i` of factor keyword `name` (an empty scope when there is none).
    function command_occurrence(self, name, i) result(occ)
        class(command_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer, intent(in) :: i
        type(keyword_set_t) :: occ
        integer :: k
        occ%file = self%file; occ%command = self%name; occ%scope = name
        occ%line = self%line; occ%col = self%col
        do k = 1, self%nfactor
            if (self%factors(k)%name == name) then
                if (i >= 1 .and. i <= size(self%factors(k)%occ)) occ = self%factors(k)%occ(i)
                return
            end if
        end do
    end function command_occurrence

    !> Appends a factor keyword with its occurrences (used by validation).
    subroutine command_add_factor(self, factor)
        class(command_t), intent(inout) :: self
        type(factor_value_t), intent(in) :: factor
        type(factor_value_t), allocatable :: bigger(:)
        if (.not. allocated(self%factors)) allocate (self%factors(4))
        if (self%nfactor == size(self%factors)) then
            allocate (bigger(2 * size(self%factors)))
            bigger(1:self%nfactor) = self%factors(1:self%nfactor)
            call move_alloc(bigger, self%factors)
        end if
        self%nfactor = self%nfactor + 1
        self%factors(self%nfactor) = factor
    end subroutine command_add_factor

end module deck_command
